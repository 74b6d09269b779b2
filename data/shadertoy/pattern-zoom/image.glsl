// A stochtex pattern in a ShaderToy program: stochtex_sample(uv) is the
// filtered marble preset (uv in example periods; the footprint comes from
// this fragment's derivatives), zoomed in and out over time; the left half
// is filtered, the right half shows one unfiltered look-up per pixel
// through the same include (a zero footprint) for comparison.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float zoom = exp2(4.0 * sin(0.3 * iTime));              // texels per pixel: 1/16 to 16
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) * zoom / 256.0 + vec2(0.3, 0.7);
    vec3 linear = fragCoord.x < 0.5 * iResolution.x ? stochtex_sample(uv).rgb
                                                     : filteredColour(uv, vec2(0.0), vec2(0.0));
    fragColor = vec4(srgbFromLinear3(linear), 1.0);         // ShaderToy shows display codes
    if (abs(fragCoord.x - 0.5 * iResolution.x) < 1.0) fragColor = vec4(1.0);
}
