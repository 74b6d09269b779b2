// The dye through a warm palette; keys 1 and 2 (codes 49, 50) show one channel alone.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec4 d = texture(iChannel0, uv);
    vec3 colour = vec3(d.x, 0.6 * d.x + 0.4 * d.y, 0.2 + 0.3 * d.y);
    if (texelFetch(iChannel1, ivec2(49, 2), 0).x > 0.5) colour = vec3(d.x);
    if (texelFetch(iChannel1, ivec2(50, 2), 0).x > 0.5) colour = vec3(d.y);
    fragColor = vec4(clamp(colour, 0.0, 1.0), 1.0);
}
