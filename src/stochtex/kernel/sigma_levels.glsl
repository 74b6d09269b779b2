// Looking up the prefiltered colormap H̄(μ, σ_x, σ_y) between its σ levels
// (paper §5). Kernel file: GLSL and C++, see kernel/glsl.h.
//
// Paper mode: levels σ_k = 2^k/256, k = 0…5, nearest in log2 σ (below 1/256
// the finest). Smooth mode: level 0 is σ = 0, level k ≥ 1 is 2^(k−1)/256,
// linear below 1/256 and in log2 σ above, so nothing pops as σ̂ changes.

// The continuous level coordinate of σ along one axis, in [0, levels − 1].
inline float sigmaLevelCoordinate(float sigma, bool paper, int levels) {
    float top = float(levels - 1);
    float s256 = sigma * 256.0f;
    // σ ≤ 0 and a NaN σ (a broken footprint) read level 0: !(x > 0) holds for
    // NaN, which max(σ, 0) would pass on to int() below. +inf reads the top.
    if (!(s256 > 0.0f)) return 0.0f;
    if (paper) {
        // round(log2 x) = ⌊log2(√2·x)⌋, read off the float's exponent field.
        float y = s256 * 1.41421356f;
        if (!(y >= 2.0f)) return 0.0f;
        return min(float(int(floatBitsToUint(y) >> 23u) - 127), top);
    }
    return min(s256 <= 1.0f ? s256 : 1.0f + log2(s256), top);
}

// A field bounded in [0, 1] (a table's output read by the next table) is
// far from Gaussian at large footprints (Figure 14's g has its mass near 0
// and 1), so a table axis it feeds is prefiltered with the Beta
// distribution of its mean m and variance σ² instead (docs/MATH.md, "A
// bounded field as a Beta"). Its shape is ν = σ²/(m(1 − m)) ∈ [0, 1]; the
// axis's levels are levels of τ = √ν/2, the Beta's deviation at m = ½ (where
// it equals σ), clamped to ½ (ν = 1, the two spikes at 0 and 1); a mean at
// an end (or beyond, where the lookup clamps it) reads the same entry at
// every level.
//
// Paper mode: the σ levels, nearest in log2 τ. Smooth mode: τ = 0, then
// 2^k/256 for k = 0…6, then √2/4 (the arcsine distribution, ν = ½, which a
// uniform angle's sine profile becomes at large footprints) and ½: the same
// count as the σ levels (PrefilteredColormap::betaLevels), with the last
// octave halved where τ is largest. Between levels the coordinate is linear
// in τ², i.e. in the variance at a given mean: E[T(X)] of a quadratic T is
// linear in the variance, so a squared bounded field's E[g²] is exact
// between levels, where log2 interpolation is off by up to a fifth of the
// variance.
inline float betaLevelCoordinate(float mean, float sigma, bool paper, int levels) {
    if (!(sigma > 0.0f)) return 0.0f;  // a NaN σ too, as sigmaLevelCoordinate
    float spread = mean * (1.0f - mean);
    float tau = spread > 0.0f ? min(sigma / (2.0f * sqrt(spread)), 0.5f) : 0.5f;
    if (paper) return sigmaLevelCoordinate(tau, true, levels);
    float top = float(levels - 1);
    float t = tau * 256.0f;  // level k = 1…7 is t = 2^(k−1)
    if (t <= 1.0f) return min(t * t, top);
    if (t < 64.0f) {
        // t = 2^e · r with r ∈ [1, 2): between levels e + 1 and e + 2, whose τ²
        // are 4^e and 4^(e+1) (in units of 256⁻²): weight (r² − 1)/3.
        int e = int(floatBitsToUint(t) >> 23u) - 127;
        float r = t / exp2(float(e));
        return min(1.0f + float(e) + (r * r - 1.0f) / 3.0f, top);
    }
    // Levels 7, 8, 9 at t² = 4096 · (1, 2, 4).
    float q = t * t / 4096.0f;
    return min(q <= 2.0f ? 6.0f + q : 7.0f + 0.5f * q, top);
}

// The (up to) four layers (kx, ky) a lookup blends and the bilinear weights.
struct LayerBlend {
    ivec2 k0;  // layer (x0, y0)
    ivec2 k1;  // layer (x1, y1)
    vec2 f;    // weights of x1 and y1
};

// From the two axes' level coordinates.
inline LayerBlend levelBlend(float cx, float cy, int levels) {
    LayerBlend b;
    b.k0 = ivec2(min(int(cx), levels - 1), min(int(cy), levels - 1));
    b.f = vec2(cx - float(b.k0.x), cy - float(b.k0.y));
    b.k1 = ivec2(min(b.k0.x + 1, levels - 1), min(b.k0.y + 1, levels - 1));
    return b;
}

// A table whose axes are all Gaussian.
inline LayerBlend layerBlend(vec2 sigma, bool paper, int levels) {
    return levelBlend(sigmaLevelCoordinate(sigma.x, paper, levels), sigmaLevelCoordinate(sigma.y, paper, levels),
                      levels);
}

// A table at mean μ and deviations σ whose axes with beta ≠ 0 are Beta axes.
inline LayerBlend tableLayerBlend(vec2 mean, vec2 sigma, ivec2 beta, bool paper, int levels) {
    return levelBlend(beta.x != 0 ? betaLevelCoordinate(mean.x, sigma.x, paper, levels)
                                  : sigmaLevelCoordinate(sigma.x, paper, levels),
                      beta.y != 0 ? betaLevelCoordinate(mean.y, sigma.y, paper, levels)
                                  : sigmaLevelCoordinate(sigma.y, paper, levels),
                      levels);
}

// The layers' colours (x0,y0), (x1,y0), (x0,y1), (x1,y1) blended.
inline vec3 layerMix(vec3 c00, vec3 c10, vec3 c01, vec3 c11, vec2 f) {
    vec3 top = c00 + f.x * (c10 - c00);
    vec3 bottom = c01 + f.x * (c11 - c01);
    return top + f.y * (bottom - top);
}
