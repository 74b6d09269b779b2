// The filtered pattern Ŝ = H̄(μ̂, σ̂) (paper §4–5): the
// footprint comes from the rasterizer's derivatives of uv, is split into
// OpenGL-style anisotropic probes, each probe into two pyramid levels
// (trilinear), and the texel statistics of eq. 8, 12, 17 are combined by
// eq. 9, 14–15, 18–19, by the kernel's functions (kernel/footprint.glsl,
// moments.glsl, sigma_levels.glsl), which filter/ and pattern/ call on the
// CPU.
uniform sampler2D uStatsX, uStatsY, uCovariance;  // RG32F mip levels: (E_l, V_l) / (E_l, C_l)
uniform sampler2DArray uTable;                     // RGBA32F, layer kx·levels + ky
uniform bool uHasCovariance;   // covariances from uCovariance (shared offsets and a response that reads them)
uniform bool uDeliotHeitz;     // one constant variance per level
uniform float uAverageX[16], uAverageY[16], uAverageCov[16];
uniform int uMaxLod;
uniform int uAniso;            // K
uniform bool uSmooth;          // smooth table (else paper)
uniform int uTableLevels;      // σ levels per axis

// Texel statistics of one level at one probe: (mean x, mean y, var x, var y) and cov.
void texelStats(vec2 uv, int level, out vec4 stats, out float cov) {
    Stencil s = triangleGrid(uv, uDensity);
    vec2 fu = fract(uv);
    vec3 mx, my, vx, vy, c;
    for (int i = 0; i < 3; ++i) {
        uvec2 vertex = stencilVertex(s, i);
        vec2 px = fract(fu + tileOffset(vertex, uSeedX));
        vec2 py = fract(fu + tileOffset(vertex, uSeedY));
        vec2 ex = periodicBilinearLod(uStatsX, px, level).rg;
        vec2 ey = periodicBilinearLod(uStatsY, py, level).rg;
        mx[i] = ex.r;
        vx[i] = ex.g;
        my[i] = ey.r;
        vy[i] = ey.g;
        // The covariance is fetched only with shared offsets (else it is 0).
        c[i] = uHasCovariance ? periodicBilinearLod(uCovariance, px, level).g : 0.0;
    }
    stats = vec4(blendMean(uMeanX, s.w, mx), blendMean(uMeanY, s.w, my), blendVariance(s.w, vx), blendVariance(s.w, vy));
    cov = uHasCovariance ? blendVariance(s.w, c) : 0.0;
    if (uDeliotHeitz) {
        stats.zw = vec2(uAverageX[level], uAverageY[level]);
        cov = uHasCovariance ? uAverageCov[level] : 0.0;
    }
}

vec3 tableLayer(int kx, int ky, vec2 mu) {
    int layer = kx * uTableLevels + ky;
    ivec2 r = textureSize(uTable, 0).xy;
    vec2 fxy = clamp(mu, 0.0, 1.0) * vec2(r - 1);
    ivec2 i0 = min(ivec2(fxy), r - 2);
    vec2 t = fxy - vec2(i0);
    vec3 a0 = texelFetch(uTable, ivec3(i0, layer), 0).rgb, a1 = texelFetch(uTable, ivec3(i0 + ivec2(1, 0), layer), 0).rgb;
    vec3 b0 = texelFetch(uTable, ivec3(i0 + ivec2(0, 1), layer), 0).rgb;
    vec3 b1 = texelFetch(uTable, ivec3(i0 + ivec2(1, 1), layer), 0).rgb;
    vec3 top = a0 + t.x * (a1 - a0), bottom = b0 + t.x * (b1 - b0);
    return top + t.y * (bottom - top);
}

vec3 prefiltered(vec2 mu, vec2 sigma) {
    LayerBlend b = layerBlend(sigma, !uSmooth, uTableLevels);
    if (b.f.x == 0.0 && b.f.y == 0.0) return tableLayer(b.k0.x, b.k0.y, mu);
    return layerMix(tableLayer(b.k0.x, b.k0.y, mu), tableLayer(b.k1.x, b.k0.y, mu), tableLayer(b.k0.x, b.k1.y, mu),
                    tableLayer(b.k1.x, b.k1.y, mu), b.f);
}

// Ŝ for the footprint of uv with Jacobian columns jx, jy (uv per pixel).
vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {
    ProbeLayout probes = probeLayout(jx, jy, 1.0 / uInvW, uAniso, uMaxLod);
    ProbeLevels levels = probeLevels(probes.lod, uMaxLod, probes.count);
    vec4 st;
    float c;
    if (isSingleTexel(probes.count, levels.frac)) {
        texelStats(uv, levels.l0, st, c);
        return prefiltered(st.xy, sqrt(max(st.zw, vec2(0.0))));
    }
    Moments sums;
    for (int k = 0; k < probes.count; ++k) {
        vec2 p = uv + probePosition(k, probes.count) * probes.axis;
        texelStats(p, levels.l0, st, c);
        if (k == 0) sums = momentsAbout(st.xy);
        sums = momentsAdd(sums, levels.w0, st.xy, st.zw, c);
        if (levels.w1 > 0.0) {
            texelStats(p, levels.l1, st, c);
            sums = momentsAdd(sums, levels.w1, st.xy, st.zw, c);
        }
    }
    FootprintMoments r = momentsResult(sums);
    return prefiltered(r.mean, sqrt(r.var));
}
