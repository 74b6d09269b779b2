// The unfiltered pattern S at a point: the response at N(u) with no spread
// (pointResponse, defined by the response chunk: H(N_x, N_y), or the
// normal map's shading of the slopes N).
uniform sampler2D uExampleX, uExampleY;   // R32F, W×W
uniform sampler2D uInverseX, uInverseY;   // T⁻¹ LUTs (n × 1)

// The point response (pattern/response.h); declared here, defined by the
// response chunk the program recipe names, assembled after this file.
vec3 pointResponse(vec2 n);

vec3 unfilteredColour(vec2 uv) {
    Stencil s = triangleGrid(uv, uPattern.gridDensity);
    vec2 fu = fract(uv);
    float nx = tilingBlending(uExampleX, uPattern.meanX, uPattern.seedX, s, fu);
    float ny = tilingBlending(uExampleY, uPattern.meanY, uPattern.seedY, s, fu);
    if (uPattern.gaussianizedX != 0) nx = inverseTransform(uInverseX, nx);
    if (uPattern.gaussianizedY != 0) ny = inverseTransform(uInverseY, ny);
    return pointResponse(vec2(nx, ny));
}
