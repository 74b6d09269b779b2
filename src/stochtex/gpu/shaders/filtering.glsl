// The footprint statistics of a pair of tiled noises (paper §4): the
// footprint (the camera's Jacobian or the rasterizer's derivatives of uv) is
// split into OpenGL-style anisotropic probes, each probe into two pyramid
// levels (trilinear), and the texel statistics of eq. 8, 12, 17 are combined
// by eq. 9, 14–15, 18–19, by the kernel's functions (kernel/footprint.glsl,
// moments.glsl), which filter/ and pattern/ call on the CPU. The pattern's
// pair is pattern_filtering.glsl's; a texture graph's pairs are its
// generated chunk's (gpu/gpu_graph.cpp).
#include "stochtex/kernel/footprint.glsl"
#include "stochtex/kernel/moments.glsl"

// One pair of tiled noises whose statistics are estimated together: the
// pattern's (N_x, N_y), read from uPattern by patternPair(), or a pair of a
// texture graph's leaves (gpu/gpu_graph.cpp writes them as constants). Their
// pyramids are passed beside it (GLSL cannot keep samplers in a struct).
struct NoisePair {
    vec2 mean;          // μ of each example
    uvec2 seed;         // tile-offset seeds
    int hasCovariance;  // 1: covariances fetched and used (a shared-offset pair)
    int deliotHeitz;    // 1: uPattern.averageMoments instead of eq. 12 (the pattern's pair only)
    int maxLod;         // L = log2 W
    float exampleSize;  // W
};

// Tile i's statistics at one level: (E_l, V_l) of each noise and C_l.
struct TileStats {
    vec2 x;  // (mean, variance) of N_x's tile
    vec2 y;
    float c; // covariance (0 without the pair's hasCovariance: not fetched)
};

TileStats tileStats(sampler2D statsX, sampler2D statsY, sampler2D covariance, NoisePair pair, Stencil s, int i,
                    vec2 fu, int level) {
    uvec2 vertex = stencilVertex(s, i);
    vec2 ox = tileOffset(vertex, pair.seed.x), oy = tileOffset(vertex, pair.seed.y);
    TileStats t;
    t.x = periodicBilinearLod(statsX, fu, ox, level).rg;
    t.y = periodicBilinearLod(statsY, fu, oy, level).rg;
    t.c = pair.hasCovariance != 0 ? periodicBilinearLod(covariance, fu, ox, level).g : 0.0;
    return t;
}

// Texel statistics of one level at one probe: (mean x, mean y, var x, var y)
// and cov (eq. 8, 12, 17 by the kernel's blendMean / blendVariance).
void texelStats(sampler2D statsX, sampler2D statsY, sampler2D covariance, NoisePair pair, vec2 uv, int level,
                out vec4 stats, out float cov) {
    Stencil s = triangleGrid(uv, uPattern.gridDensity);
    vec2 fu = fract(uv);
    TileStats a = tileStats(statsX, statsY, covariance, pair, s, 0, fu, level);
    TileStats b = tileStats(statsX, statsY, covariance, pair, s, 1, fu, level);
    TileStats c = tileStats(statsX, statsY, covariance, pair, s, 2, fu, level);
    stats = vec4(blendMean(pair.mean.x, s.w, vec3(a.x.x, b.x.x, c.x.x)),
                 blendMean(pair.mean.y, s.w, vec3(a.y.x, b.y.x, c.y.x)),
                 blendVariance(s.w, vec3(a.x.y, b.x.y, c.x.y)), blendVariance(s.w, vec3(a.y.y, b.y.y, c.y.y)));
    cov = pair.hasCovariance != 0 ? blendVariance(s.w, vec3(a.c, b.c, c.c)) : 0.0;
    if (pair.deliotHeitz != 0) {
        vec4 average = uPattern.averageMoments[level];
        stats.zw = average.xy;
        cov = pair.hasCovariance != 0 ? average.z : 0.0;
    }
}

// The statistics (μ̂, σ̂², ĉov) of a pair over the footprint of uv with
// Jacobian columns jx, jy (uv per pixel). One loop for every footprint, a
// single texel included (its statistics are then taken as they are): a
// branch around the loop would make SIMD lanes run both paths.
FootprintMoments pairStatistics(sampler2D statsX, sampler2D statsY, sampler2D covariance, NoisePair pair, vec2 uv,
                                vec2 jx, vec2 jy) {
    ProbeLayout probes = probeLayout(jx, jy, pair.exampleSize, uPattern.aniso, pair.maxLod);
    ProbeLevels levels = probeLevels(probes.lod, pair.maxLod, probes.count);
    vec4 st, first;
    float c, firstCov;
    Moments sums;
    for (int k = 0; k < probes.count; ++k) {
        vec2 p = uv + probePosition(k, probes.count) * probes.axis;
        texelStats(statsX, statsY, covariance, pair, p, levels.l0, st, c);
        if (k == 0) {
            sums = momentsAbout(st.xy);
            first = st;
            firstCov = c;
        }
        sums = momentsAdd(sums, levels.w0, st.xy, st.zw, c);
        if (levels.w1 > 0.0) {
            texelStats(statsX, statsY, covariance, pair, p, levels.l1, st, c);
            sums = momentsAdd(sums, levels.w1, st.xy, st.zw, c);
        }
    }
    FootprintMoments r = momentsResult(sums);
    if (isSingleTexel(probes.count, levels.frac)) {
        r.mean = first.xy;
        r.var = max(first.zw, vec2(0.0));
        r.cov = firstCov;
    }
    return r;
}
