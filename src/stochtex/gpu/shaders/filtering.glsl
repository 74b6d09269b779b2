// The filtered pattern Ŝ = H̄(μ̂, σ̂) (paper §4–5): the
// footprint comes from the rasterizer's derivatives of uv, is split into
// OpenGL-style anisotropic probes, each probe into two pyramid levels
// (trilinear), and the texel statistics of eq. 8, 12, 17 are combined by
// eq. 9, 14–15, 18–19. Mirrors filter/footprint*.cpp and
// pattern/prefiltered_colormap.cpp.
uniform sampler2D uStatsX, uStatsY, uCovariance;  // RG32F mip levels: (E_l, V_l) / (E_l, C_l)
uniform sampler2DArray uTable;                     // RGBA32F, layer kx·levels + ky
uniform bool uShared;          // shared offsets: covariances from uCovariance
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
    vec3 w2 = s.w * s.w;
    vec2 meanAcc = vec2(uMeanX, uMeanY), varAcc = vec2(0.0);
    cov = 0.0;
    for (int i = 0; i < 3; ++i) {
        uvec2 vertex = stencilVertex(s, i);
        vec2 px = fract(fu + tileOffset(vertex, uSeedX));
        vec2 py = fract(fu + tileOffset(vertex, uSeedY));
        vec2 ex = periodicBilinearLod(uStatsX, px, level).rg;
        vec2 ey = periodicBilinearLod(uStatsY, py, level).rg;
        meanAcc += s.w[i] * vec2(ex.r - uMeanX, ey.r - uMeanY);
        varAcc += w2[i] * vec2(ex.g, ey.g);
        if (uShared) cov += w2[i] * periodicBilinearLod(uCovariance, px, level).g;
    }
    if (uDeliotHeitz) {
        varAcc = vec2(uAverageX[level], uAverageY[level]);
        cov = uShared ? uAverageCov[level] : 0.0;
    }
    stats = vec4(meanAcc, varAcc);
}

// σ level coordinate: nearest in log2 (paper) or continuous (smooth).
float levelCoordinate(float sigma) {
    float top = float(uTableLevels - 1);
    float s256 = max(sigma, 0.0) * 256.0;
    if (!uSmooth) {
        float y = s256 * 1.41421356;
        return y >= 2.0 ? min(floor(log2(y)), top) : 0.0;
    }
    return min(s256 <= 1.0 ? s256 : 1.0 + log2(s256), top);
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
    float cx = levelCoordinate(sigma.x), cy = levelCoordinate(sigma.y);
    int n = uTableLevels;
    int x0 = min(int(cx), n - 1), y0 = min(int(cy), n - 1);
    float fx = cx - float(x0), fy = cy - float(y0);
    if (fx == 0.0 && fy == 0.0) return tableLayer(x0, y0, mu);
    int x1 = min(x0 + 1, n - 1), y1 = min(y0 + 1, n - 1);
    vec3 top = mix(tableLayer(x0, y0, mu), tableLayer(x1, y0, mu), fx);
    vec3 bottom = mix(tableLayer(x0, y1, mu), tableLayer(x1, y1, mu), fx);
    return mix(top, bottom, fy);
}

// Ŝ for the footprint of uv with Jacobian columns jx, jy (uv per pixel).
vec3 filteredColour(vec2 uv, vec2 jx, vec2 jy) {
    float w = 1.0 / uInvW;
    // OpenGL anisotropic filtering (EXT_texture_filter_anisotropic).
    float px = w * length(jx), py = w * length(jy);
    bool xMajor = px >= py;
    float pmax = max(px, py), pmin = min(px, py);
    int n = 1;
    if (uAniso > 1 && pmin > 0.0) n = int(min(ceil(pmax / pmin - 1e-6), float(uAniso)));
    else if (uAniso > 1 && pmax > 0.0) n = uAniso;
    n = clamp(n, 1, max(uAniso, 1));
    float rho = pmax / float(n);
    float lod = rho > 0.0 ? clamp(log2(rho), 0.0, float(uMaxLod)) : 0.0;
    vec2 axis = xMajor ? jx : jy;
    int l0 = min(int(lod), uMaxLod);
    float frac = lod - float(l0);
    int l1 = min(l0 + 1, uMaxLod);
    // Σ w_P over probes × levels, centred on the first texel's mean so the
    // float subtraction m2 − μ² does not cancel.
    vec2 shift = vec2(0.0);
    vec2 m = vec2(0.0), m2 = vec2(0.0);
    float mxy = 0.0;
    bool first = true;
    vec4 single;
    float singleCov = 0.0;
    for (int k = 0; k < n; ++k) {
        float t = n == 1 ? 0.0 : (float(k) + 0.5) / float(n) - 0.5;
        vec2 p = uv + t * axis;
        for (int side = 0; side < 2; ++side) {
            float wp = (side == 0 ? 1.0 - frac : frac) / float(n);
            if (wp <= 0.0) continue;
            vec4 st;
            float c;
            texelStats(p, side == 0 ? l0 : l1, st, c);
            if (first) {
                shift = st.xy;
                single = st;
                singleCov = c;
                first = false;
            }
            vec2 d = st.xy - shift;
            m += wp * d;
            m2 += wp * (d * d + st.zw);
            mxy += wp * (d.x * d.y + c);
        }
    }
    vec2 mu, var;
    if (n == 1 && frac == 0.0) {
        mu = single.xy;  // one texel footprint: its own statistics
        var = max(single.zw, vec2(0.0));
    } else {
        mu = shift + m;
        var = max(m2 - m * m, vec2(0.0));
    }
    return prefiltered(mu, sqrt(var));
}
