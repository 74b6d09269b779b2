// The filtered pattern Ŝ = H̄(μ̂, σ̂) (paper §4–5): the statistics of the
// pattern's pair (N_x, N_y) over a footprint by the kernel's estimator loop
// (kernel/estimate.glsl) over this file's texel source, and a response
// chunk that turns them into the colour (footprintResponse).
#include "stochtex/gpu/shaders/filtering.glsl"
#include "stochtex/kernel/estimate.glsl"
uniform sampler2D uStatsX, uStatsY, uCovariance;  // RG32F mip levels: (E_l, V_l) / (E_l, C_l)

TexelSource patternSource() {
    return TexelSource(0, vec2(uPattern.meanX, uPattern.meanY), uvec2(uPattern.seedX, uPattern.seedY),
                       uPattern.hasCovariance, uPattern.maxLod, 1.0 / uPattern.invExampleSize);
}

ProbeTexels probeTexels(TexelSource s, vec2 uv, ProbeLevels levels) {
    return pairProbeTexels(uStatsX, uStatsY, uCovariance, s, uv, levels);
}

vec3 levelAverages(TexelSource s, int level) {
    return uPattern.averageMoments[level].xyz;
}

// The response: the colour of a footprint whose N has these statistics
// (mean, variances, covariance; pattern/response.h). Declared here and
// defined by the response chunk the program recipe names (gpu/programs.cpp:
// response_prefiltered_colormap.glsl, …), assembled after this file.
vec3 footprintResponse(vec2 mean, vec2 var, float cov);

// The pattern's N over the footprint of uv (Jacobian columns jx, jy).
FootprintMoments footprintStatistics(vec2 uv, vec2 jx, vec2 jy) {
    TexelSource s = patternSource();
    return jacobianEstimate(s, uv, jx, jy, s.exampleSize, uPattern.aniso, s.maxLod, uPattern.deliotHeitz != 0,
                            s.hasCovariance != 0);
}

// Ŝ for the footprint of uv: the response of its statistics.
vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {
    FootprintMoments r = footprintStatistics(uv, jx, jy);
    return footprintResponse(r.mean, r.var, r.cov);
}
