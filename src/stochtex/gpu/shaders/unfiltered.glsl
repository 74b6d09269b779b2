// The unfiltered pattern S = H(N_x, N_y) at a point.
uniform sampler2D uExampleX, uExampleY;   // R32F, W×W
uniform sampler2D uInverseX, uInverseY;   // T⁻¹ LUTs (n × 1)
uniform sampler2DArray uColormap;         // RGB32F table, one layer
uniform bool uGaussianizedX, uGaussianizedY;

vec3 unfilteredColour(vec2 uv) {
    Stencil s = triangleGrid(uv, uDensity);
    vec2 fu = fract(uv);
    float nx = tilingBlending(uExampleX, uMeanX, uSeedX, s, fu);
    float ny = tilingBlending(uExampleY, uMeanY, uSeedY, s, fu);
    if (uGaussianizedX) nx = inverseTransform(uInverseX, nx);
    if (uGaussianizedY) ny = inverseTransform(uInverseY, ny);
    return tableLookup(uColormap, 0, vec2(nx, ny));
}
