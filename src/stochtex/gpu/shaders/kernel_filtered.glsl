// The compute kernel's colour: the filtered pattern, footprint = the
// camera's Jacobian (a compute shader has no derivatives).
vec3 pixelColour(vec2 uv, vec2 jx, vec2 jy) { return filteredColour(uv, jx, jy); }
