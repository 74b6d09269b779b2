// Dye advected by the field (semi-Lagrangian: read where the fluid came
// from, previous frame), with fresh noise injected at the left edge.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec2 from = uv - velocity(uv, iTime);
    vec4 dye = texture(iChannel0, from) * 0.99;
    float source = 0.08 * smoothstep(0.08, 0.0, uv.x) * texture(iChannel1, vec2(uv.y * 2.0, iTime * 0.05)).r;
    fragColor = iFrame == 0 ? vec4(0.0) : dye + vec4(source, 12.0 * source * source, 0.0, 0.0);
}
