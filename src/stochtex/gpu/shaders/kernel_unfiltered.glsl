// The compute kernel's colour: the unfiltered pattern at the pixel centre.
vec3 pixelColour(vec2 uv, vec2 jx, vec2 jy) { return unfilteredColour(uv); }
