// The filtered pattern at each pixel of the view. The footprint is the
// camera's exact Jacobian (as on the CPU), or, with uRasterizerDerivatives,
// the rasterizer's dFdx/dFdy of uv: what an engine has for arbitrary
// geometry (one-sided differences within each 2×2 quad).
uniform bool uRasterizerDerivatives;
layout(location = 0) out vec4 fragColour;

void main() {
    bool sky;
    vec2 jx, jy;
    vec2 uv = viewUv(gl_FragCoord.xy, jx, jy, sky);
    if (uRasterizerDerivatives) {  // a uniform branch: the whole quad takes it
        jx = dFdx(uv);
        jy = dFdy(uv);
        // A quad neighbour past the horizon gives non-finite derivatives.
        sky = sky || any(isinf(jx)) || any(isnan(jx)) || any(isinf(jy)) || any(isnan(jy));
    }
    fragColour = vec4(sky ? uSky : filteredColour(uv, jx, jy), 1.0);
}
