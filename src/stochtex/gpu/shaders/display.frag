// A texture shown in a rectangle of a window (TextureDisplay): the rectangle
// covers the texture (nearest texel, so at one texel per pixel the window
// holds the texture exactly). A render target holds linear light with image
// row 0 in GL row 0 (as `render` reads it back), while the window shows GL
// row 0 at the bottom: such a texture is turned over (uTurnOver) and gets
// the sRGB codes a PNG of `render` holds (uEncode, kernel/colour.glsl).
#include "stochtex/kernel/colour.glsl"
uniform sampler2D uImage;
uniform ivec4 uRect;  // x, y (GL window coordinates, bottom left), width, height
uniform bool uTurnOver;
uniform bool uEncode;
uniform float uOpacity;
uniform bool uAlpha;  // the texture's alpha scales the opacity (an overlay whose zero is see-through)
layout(location = 0) out vec4 fragColour;

void main() {
    ivec2 size = textureSize(uImage, 0);
    vec2 f = (gl_FragCoord.xy - vec2(uRect.xy)) / vec2(uRect.zw);
    ivec2 p = clamp(ivec2(floor(f * vec2(size))), ivec2(0), size - 1);
    if (uTurnOver) p.y = size.y - 1 - p.y;
    vec4 t = texelFetch(uImage, p, 0);
    vec3 c = t.rgb;
    fragColour = vec4(uEncode ? srgbFromLinear3(c) : c, uAlpha ? t.a * uOpacity : uOpacity);
}
