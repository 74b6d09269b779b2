// The filtered pattern Ŝ = H̄(μ̂, σ̂) (paper §4–5): the
// footprint comes from the rasterizer's derivatives of uv, is split into
// OpenGL-style anisotropic probes, each probe into two pyramid levels
// (trilinear), and the texel statistics of eq. 8, 12, 17 are combined by
// eq. 9, 14–15, 18–19, by the kernel's functions (kernel/footprint.glsl,
// moments.glsl), which filter/ and pattern/ call on the CPU. A response
// chunk turns the statistics into the colour (footprintResponse).
uniform sampler2D uStatsX, uStatsY, uCovariance;  // RG32F mip levels: (E_l, V_l) / (E_l, C_l)

// Tile i's statistics at one level: (E_l, V_l) of each noise and C_l.
struct TileStats {
    vec2 x;  // (mean, variance) of N_x's tile
    vec2 y;
    float c; // covariance (0 without uPattern.hasCovariance: not fetched)
};

TileStats tileStats(Stencil s, int i, vec2 fu, int level) {
    uvec2 vertex = stencilVertex(s, i);
    vec2 ox = tileOffset(vertex, uPattern.seedX), oy = tileOffset(vertex, uPattern.seedY);
    TileStats t;
    t.x = periodicBilinearLod(uStatsX, fu, ox, level).rg;
    t.y = periodicBilinearLod(uStatsY, fu, oy, level).rg;
    t.c = uPattern.hasCovariance != 0 ? periodicBilinearLod(uCovariance, fu, ox, level).g : 0.0;
    return t;
}

// Texel statistics of one level at one probe: (mean x, mean y, var x, var y)
// and cov (eq. 8, 12, 17 by the kernel's blendMean / blendVariance).
void texelStats(vec2 uv, int level, out vec4 stats, out float cov) {
    Stencil s = triangleGrid(uv, uPattern.gridDensity);
    vec2 fu = fract(uv);
    TileStats a = tileStats(s, 0, fu, level), b = tileStats(s, 1, fu, level), c = tileStats(s, 2, fu, level);
    stats = vec4(blendMean(uPattern.meanX, s.w, vec3(a.x.x, b.x.x, c.x.x)),
                 blendMean(uPattern.meanY, s.w, vec3(a.y.x, b.y.x, c.y.x)),
                 blendVariance(s.w, vec3(a.x.y, b.x.y, c.x.y)), blendVariance(s.w, vec3(a.y.y, b.y.y, c.y.y)));
    cov = uPattern.hasCovariance != 0 ? blendVariance(s.w, vec3(a.c, b.c, c.c)) : 0.0;
    if (uPattern.deliotHeitz != 0) {
        vec4 average = uPattern.averageMoments[level];
        stats.zw = average.xy;
        cov = uPattern.hasCovariance != 0 ? average.z : 0.0;
    }
}

// The response: the colour of a footprint whose N has these statistics
// (mean, variances, covariance; pattern/response.h). Declared here and
// defined by the response chunk the program recipe names (gpu/programs.cpp:
// response_prefiltered_colormap.glsl, …), assembled after this file.
vec3 footprintResponse(vec2 mean, vec2 var, float cov);

// The statistics (μ̂, σ̂², ĉov) of N over the footprint of uv with Jacobian
// columns jx, jy (uv per pixel). One loop for every footprint, a single
// texel included (its statistics are then taken as they are): a branch
// around the loop would make SIMD lanes run both paths.
FootprintMoments footprintStatistics(vec2 uv, vec2 jx, vec2 jy) {
    ProbeLayout probes = probeLayout(jx, jy, 1.0 / uPattern.invExampleSize, uPattern.aniso, uPattern.maxLod);
    ProbeLevels levels = probeLevels(probes.lod, uPattern.maxLod, probes.count);
    vec4 st, first;
    float c, firstCov;
    Moments sums;
    for (int k = 0; k < probes.count; ++k) {
        vec2 p = uv + probePosition(k, probes.count) * probes.axis;
        texelStats(p, levels.l0, st, c);
        if (k == 0) {
            sums = momentsAbout(st.xy);
            first = st;
            firstCov = c;
        }
        sums = momentsAdd(sums, levels.w0, st.xy, st.zw, c);
        if (levels.w1 > 0.0) {
            texelStats(p, levels.l1, st, c);
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

// Ŝ for the footprint of uv: the response of its statistics.
vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {
    FootprintMoments r = footprintStatistics(uv, jx, jy);
    return footprintResponse(r.mean, r.var, r.cov);
}
