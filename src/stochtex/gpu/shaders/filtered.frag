// The filtered pattern at each pixel of the view; the footprint comes from
// the rasterizer's derivatives of uv.
layout(location = 0) out vec4 fragColor;

void main() {
    bool sky;
    vec2 uv = viewUv(gl_FragCoord.xy, sky);
    vec2 jx = dFdx(uv), jy = dFdy(uv);  // before any branch: derivatives need the whole quad
    // A neighbour in the quad past the horizon gives non-finite derivatives:
    // sky, as the CPU's rule (any of the ±½-pixel points misses the plane).
    sky = sky || any(isinf(jx)) || any(isnan(jx)) || any(isinf(jy)) || any(isnan(jy));
    fragColor = vec4(sky ? uSky : filteredColour(uv, jx, jy), 1.0);
}
