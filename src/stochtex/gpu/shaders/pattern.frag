// The unfiltered pattern S = H(N_x, N_y) at each pixel centre.
uniform sampler2D uExampleX, uExampleY;   // R32F, W×W
uniform sampler2D uInverseX, uInverseY;   // T⁻¹ LUTs (n × 1)
uniform sampler2D uColormap;              // RGB32F table
uniform float uMeanX, uMeanY;
uniform uint uSeedX, uSeedY;
uniform bool uGaussianizedX, uGaussianizedY;
uniform float uDensity;                   // grid density (2√3)

layout(location = 0) out vec4 fragColor;

void main() {
    bool sky;
    vec2 uv = viewUv(gl_FragCoord.xy, sky);
    if (sky) {
        fragColor = vec4(uSky, 1.0);
        return;
    }
    Stencil s = triangleGrid(uv, uDensity);
    vec2 fu = fract(uv);
    float nx = tilingBlending(uExampleX, uMeanX, uSeedX, s, fu);
    float ny = tilingBlending(uExampleY, uMeanY, uSeedY, s, fu);
    if (uGaussianizedX) nx = inverseTransform(uInverseX, nx);
    if (uGaussianizedY) ny = inverseTransform(uInverseY, ny);
    fragColor = vec4(colormapLookup(uColormap, vec2(nx, ny)), 1.0);
}
