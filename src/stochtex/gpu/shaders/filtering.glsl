// The GPU's texel source for the footprint estimators (paper §4): the loop
// over probes and levels, the sums, the Deliot–Heitz substitution and the
// single-texel rule are the kernel's (kernel/estimate.glsl), the one loop
// the CPU runs too; this file declares what the loop reads — a pair of
// tiled noises (TexelSource) and its two functions, probeTexels and
// levelAverages — and fetches one pair's texel statistics from its
// pyramids. The functions are defined over the program's samplers by the
// pattern's chunk (pattern_filtering.glsl: its one pair) or a texture
// graph's generated chunk (gpu/gpu_graph.cpp: a branch per pair), each of
// which includes kernel/estimate.glsl after this file.
#include "stochtex/kernel/coords.glsl"
#include "stochtex/kernel/footprint.glsl"
#include "stochtex/kernel/texel_stats.glsl"

// One pair of tiled noises whose statistics are estimated together: the
// pattern's (N_x, N_y), or a pair of a texture graph's leaves (the graph's
// chunk writes them as constants). Their pyramids are not in it (GLSL cannot
// keep samplers in a struct): the host picks them by `pair`.
struct TexelSource {
    int pair;           // which of the program's pairs (0 for a pattern)
    vec2 mean;          // μ of each example
    uvec2 seed;         // tile-offset seeds
    int hasCovariance;  // 1: covariances fetched and used (a shared-offset pair)
    int maxLod;         // L = log2 W
    float exampleSize;  // W
};
ProbeTexels probeTexels(TexelSource s, vec2 uv, ProbeLevels levels);
vec3 levelAverages(TexelSource s, int level);

// How one pair's pyramid texels hold its statistics at one level: the
// export's compact formats (gpu/export.h) store them as 8-bit codes, float
// data is its own code (offset 0, scale 1, which the compiler folds away).
// With q the texels' values in the order (E_x, E_y, V_x, V_y) — the leaves'
// own textures' (x.r, y.r, x.g, y.g), or with `packedPair` one RGBA texture per
// pair holding (E_x, E_y, V_x, V_y), the paper's layout — the statistics
// are offset + scale · q, and C = cov.x + cov.y · (the covariance texel's g).
// The coding is affine, so it commutes with the bilinear blend of texels.
struct StatsCoding {
    vec4 offset;
    vec4 scale;
    vec2 cov;
    int packedPair;
};
StatsCoding statsCoding(TexelSource s, int level);

// Tile i's statistics at one level: (E_l, V_l) of each noise and C_l.
struct TileStats {
    vec2 x;  // (mean, variance) of N_x's tile
    vec2 y;
    float c; // covariance (0 without the pair's hasCovariance: not fetched)
};

TileStats tileStats(sampler2D statsX, sampler2D statsY, sampler2D covariance, TexelSource pair, StatsCoding code,
                    Stencil s, int i, vec2 fu, int level) {
    uvec2 vertex = stencilVertex(s, i);
    vec2 ox = tileOffset(vertex, pair.seed.x), oy = tileOffset(vertex, pair.seed.y);
    vec4 tx = periodicBilinearLod(statsX, fu, ox, level), ty = periodicBilinearLod(statsY, fu, oy, level);
    vec4 q = code.offset + code.scale * (code.packedPair != 0 ? vec4(tx.r, ty.g, tx.b, ty.a) : vec4(tx.r, ty.r, tx.g, ty.g));
    TileStats t;
    t.x = q.xz;
    t.y = q.yw;
    t.c = pair.hasCovariance != 0 ? code.cov.x + code.cov.y * periodicBilinearLod(covariance, fu, ox, level).g : 0.0;
    return t;
}

// Texel statistics of one level (eq. 8, 12, 17 by the kernel's blendMean /
// blendVariance), the paper's variances.
TexelStats texelStats(sampler2D statsX, sampler2D statsY, sampler2D covariance, TexelSource pair, Stencil s, vec2 fu,
                      int level) {
    StatsCoding code = statsCoding(pair, level);
    TileStats a = tileStats(statsX, statsY, covariance, pair, code, s, 0, fu, level);
    TileStats b = tileStats(statsX, statsY, covariance, pair, code, s, 1, fu, level);
    TileStats c = tileStats(statsX, statsY, covariance, pair, code, s, 2, fu, level);
    TexelStats t;
    t.mean = vec2(blendMean(pair.mean.x, s.w, vec3(a.x.x, b.x.x, c.x.x)),
                  blendMean(pair.mean.y, s.w, vec3(a.y.x, b.y.x, c.y.x)));
    t.var = vec2(blendVariance(s.w, vec3(a.x.y, b.x.y, c.x.y)), blendVariance(s.w, vec3(a.y.y, b.y.y, c.y.y)));
    t.cov = pair.hasCovariance != 0 ? blendVariance(s.w, vec3(a.c, b.c, c.c)) : 0.0;
    return t;
}

// A probe's two levels from the pyramids of one pair, on one stencil.
ProbeTexels pairProbeTexels(sampler2D statsX, sampler2D statsY, sampler2D covariance, TexelSource pair, vec2 uv,
                            ProbeLevels levels) {
    Stencil s = triangleGrid(uv, patternGrid(uPattern));
    vec2 fu = fract(uv);
    ProbeTexels t;
    t.lo = texelStats(statsX, statsY, covariance, pair, s, fu, levels.l0);
    t.hi = t.lo;
    if (levels.w1 > 0.0) t.hi = texelStats(statsX, statsY, covariance, pair, s, fu, levels.l1);
    return t;
}
