// The web page's pixel (stochtex web, gpu/web_page.h): the view's camera
// at this fragment as render --gpu has it, the point or the filtered
// colour as uFiltered says, encoded to sRGB codes for the canvas (an 8-bit
// surface the browser shows as sRGB). The canvas's first row is at its top
// and is the image's first row (render writes framebuffer row y as image
// row y), so the pixel position counts rows from the top.
#include "stochtex/kernel/colour.glsl"
uniform bool uFiltered;
layout(location = 0) out vec4 fragColour;

void main() {
    bool sky;
    vec2 jx, jy;
    vec2 uv = viewUv(vec2(gl_FragCoord.x, uViewSize.y - gl_FragCoord.y), jx, jy, sky);
    vec3 linear = sky ? uSky : uFiltered ? filteredColour(uv, jx, jy) : unfilteredColour(uv);
    fragColour = vec4(srgbFromLinear3(linear), 1.0);
}
