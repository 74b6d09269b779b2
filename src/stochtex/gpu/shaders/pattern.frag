// The unfiltered pattern S = H(N_x, N_y) at each pixel centre (the zoom
// view of the CPU renderer: uv = (offset + (p + ½)·scale) / W).
uniform sampler2D uExampleX, uExampleY;   // R32F, W×W
uniform sampler2D uInverseX, uInverseY;   // T⁻¹ LUTs (n × 1)
uniform sampler2D uColormap;              // RGB32F table
uniform float uMeanX, uMeanY;
uniform uint uSeedX, uSeedY;
uniform bool uGaussianizedX, uGaussianizedY;
uniform vec2 uOffset;                     // texels
uniform float uScale;                     // texels per pixel
uniform float uInvW;                      // 1 / W
uniform float uDensity;                   // grid density (2√3)

layout(location = 0) out vec4 fragColor;

void main() {
    vec2 uv = (uOffset + gl_FragCoord.xy * uScale) * uInvW;
    Stencil s = triangleGrid(uv, uDensity);
    vec2 fu = fract(uv);
    float nx = tilingBlending(uExampleX, uMeanX, uSeedX, s, fu);
    float ny = tilingBlending(uExampleY, uMeanY, uSeedY, s, fu);
    if (uGaussianizedX) nx = inverseTransform(uInverseX, nx);
    if (uGaussianizedY) ny = inverseTransform(uInverseY, ny);
    fragColor = vec4(colormapLookup(uColormap, vec2(nx, ny)), 1.0);
}
