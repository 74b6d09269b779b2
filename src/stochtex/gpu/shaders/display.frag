// A render target shown in a window: the target holds linear light with image
// row 0 in GL row 0 (as `render` reads it back); the window shows GL row 0 at
// the bottom, so rows are turned over, and its 8-bit buffer gets the sRGB
// codes a PNG of `render` holds (kernel/colour.glsl).
uniform sampler2D uImage;
layout(location = 0) out vec4 fragColour;

void main() {
    ivec2 size = textureSize(uImage, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(uImage, ivec2(p.x, size.y - 1 - p.y), 0).rgb;
    fragColour = vec4(srgbFromLinear3(c), 1.0);
}
