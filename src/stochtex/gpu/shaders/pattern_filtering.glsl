// The filtered pattern Ŝ = H̄(μ̂, σ̂) (paper §4–5): the statistics of the
// pattern's pair (N_x, N_y) over a footprint (filtering.glsl) and a response
// chunk that turns them into the colour (footprintResponse).
#include "stochtex/gpu/shaders/filtering.glsl"
uniform sampler2D uStatsX, uStatsY, uCovariance;  // RG32F mip levels: (E_l, V_l) / (E_l, C_l)

NoisePair patternPair() {
    return NoisePair(vec2(uPattern.meanX, uPattern.meanY), uvec2(uPattern.seedX, uPattern.seedY),
                     uPattern.hasCovariance, uPattern.deliotHeitz, uPattern.maxLod, 1.0 / uPattern.invExampleSize);
}

// The response: the colour of a footprint whose N has these statistics
// (mean, variances, covariance; pattern/response.h). Declared here and
// defined by the response chunk the program recipe names (gpu/programs.cpp:
// response_prefiltered_colormap.glsl, …), assembled after this file.
vec3 footprintResponse(vec2 mean, vec2 var, float cov);

// The pattern's N over the footprint of uv.
FootprintMoments footprintStatistics(vec2 uv, vec2 jx, vec2 jy) {
    return pairStatistics(uStatsX, uStatsY, uCovariance, patternPair(), uv, jx, jy);
}

// Ŝ for the footprint of uv: the response of its statistics.
vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {
    FootprintMoments r = footprintStatistics(uv, jx, jy);
    return footprintResponse(r.mean, r.var, r.cov);
}
