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

// The (up to) four layers (kx, ky) a lookup blends and the bilinear weights.
struct LayerBlend {
    ivec2 k0;  // layer (x0, y0)
    ivec2 k1;  // layer (x1, y1)
    vec2 f;    // weights of x1 and y1
};

inline LayerBlend layerBlend(vec2 sigma, bool paper, int levels) {
    float cx = sigmaLevelCoordinate(sigma.x, paper, levels);
    float cy = sigmaLevelCoordinate(sigma.y, paper, levels);
    LayerBlend b;
    b.k0 = ivec2(min(int(cx), levels - 1), min(int(cy), levels - 1));
    b.f = vec2(cx - float(b.k0.x), cy - float(b.k0.y));
    b.k1 = ivec2(min(b.k0.x + 1, levels - 1), min(b.k0.y + 1, levels - 1));
    return b;
}

// The layers' colours (x0,y0), (x1,y0), (x0,y1), (x1,y1) blended.
inline vec3 layerMix(vec3 c00, vec3 c10, vec3 c01, vec3 c11, vec2 f) {
    vec3 top = c00 + f.x * (c10 - c00);
    vec3 bottom = c01 + f.x * (c11 - c01);
    return top + f.y * (bottom - top);
}
