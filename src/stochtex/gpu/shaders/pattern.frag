// The unfiltered pattern at each pixel centre of the view.
layout(location = 0) out vec4 fragColour;

void main() {
    bool sky;
    vec2 jx, jy;
    vec2 uv = viewUv(gl_FragCoord.xy, jx, jy, sky);
    fragColour = vec4(sky ? uSky : unfilteredColour(uv), 1.0);
}
