// Live cells coloured by age, cells that just died in dim red.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 c = texelFetch(iChannel0, ivec2(fragCoord), 0);
    vec3 young = vec3(1.0, 0.9, 0.4), old = vec3(0.2, 0.6, 1.0);
    vec3 colour = c.x > 0.5 ? mix(young, old, c.y) : vec3(0.25 * c.z, 0.0, 0.0);
    fragColor = vec4(colour, 1.0);
}
