// The unfiltered pattern S = H(N_x, N_y) at a point.
uniform sampler2D uExampleX, uExampleY;   // R32F, W×W
uniform sampler2D uInverseX, uInverseY;   // T⁻¹ LUTs (n × 1)
uniform sampler2DArray uColormap;         // RGB32F table, one layer

vec3 unfilteredColour(vec2 uv) {
    Stencil s = triangleGrid(uv, uPattern.gridDensity);
    vec2 fu = fract(uv);
    float nx = tilingBlending(uExampleX, uPattern.meanX, uPattern.seedX, s, fu);
    float ny = tilingBlending(uExampleY, uPattern.meanY, uPattern.seedY, s, fu);
    if (uPattern.gaussianizedX != 0) nx = inverseTransform(uInverseX, nx);
    if (uPattern.gaussianizedY != 0) ny = inverseTransform(uInverseY, ny);
    return tableLookup(uColormap, 0, vec2(nx, ny));
}
