// Bilinear lookups of sampled data: periodic grids (noise examples and the
// levels of their statistics pyramids) and clamped tables (the colormap H,
// the prefiltered layers of H̄, the T⁻¹ LUT). Kernel file: GLSL and C++, see
// kernel/glsl.h.
//
// Only the addressing and the order of the interpolation live here. The
// shaders fetch texels with texelFetch and call these functions; the CPU
// tables call them directly, while the CPU's periodic grids keep their
// padded copies and vector loads (noise/periodic_grid.h) and are held to
// these functions bit for bit by tests (tests/kernel/).

// The texel coordinate, on a periodic grid of w texels with texel centres at
// (i + ½)/w, of a point p ∈ [0, 1) of one period moved by a tile offset
// o ∈ [0, 1):
//     t = (p·w + ½) + o·w, wrapped once into [½, w + ½).
// The half-texel shift makes t positive, so int(t) is a floor: it is the
// left texel of the bilinear lookup counted in a grid padded by one texel
// (padded index 0 = texel w − 1), and t − int(t) is the right texel's
// weight. p·w + ½ (texelOfPoint) and o·w come in separately because the CPU
// computes the first once per pixel and the second once per tile.
inline float texelOfPoint(float p, float w) { return p * w + 0.5f; }

inline float periodicTexel(float pointTexel, float offsetTexels, float w) {
    float t = pointTexel + offsetTexels;
    return t >= w + 0.5f ? t - w : t;
}

// The two texels (unpadded indices) and the weight of a periodic lookup at
// the texel coordinate t of periodicTexel.
struct PeriodicTaps {
    ivec2 left;   // (x, y) of the lower-left texel
    ivec2 right;  // (x, y) of the upper-right texel
    vec2 f;       // weights of the right column and the upper row
};

inline PeriodicTaps periodicTaps(vec2 t, int w) {
    ivec2 padded = ivec2(int(t.x), int(t.y));
    PeriodicTaps taps;
    taps.f = vec2(t.x - float(padded.x), t.y - float(padded.y));
    taps.left = ivec2((padded.x + w - 1) % w, (padded.y + w - 1) % w);
    taps.right = ivec2(padded.x % w, padded.y % w);
    return taps;
}

// Bilinear blend of the texels (left, bottom) … (right, top), the two columns
// first (the CPU's grids interpolate a row pair as one vector, then across).
inline vec4 blendColumnsFirst(vec4 t00, vec4 t10, vec4 t01, vec4 t11, vec2 f) {
    vec4 left = t00 + f.y * (t01 - t00);
    vec4 right = t10 + f.y * (t11 - t10);
    return left + f.x * (right - left);
}

// A table of n ≥ 2 entries with entry i at x = i/(n − 1), clamp-to-edge: the
// left entry of the lookup at x and the right one's weight.
struct TableTap {
    int i;
    float t;
};

inline TableTap tableTap(float x, int n) {
    // NaN reads entry 0: clamp(NaN, 0, 1) may be NaN, and int(NaN) an index
    // anywhere (hostile exemplars, tests/pattern/).
    float fx = (x > 0.0f ? min(x, 1.0f) : 0.0f) * float(n - 1);
    TableTap tap;
    tap.i = min(int(fx), n - 2);
    tap.t = fx - float(tap.i);
    return tap;
}

// Linear blend of a 1D table's entries i and i + 1.
inline float blendEntries(float a, float b, float t) { return a + t * (b - a); }

// Bilinear blend of a 2D table's entries (i, j) … (i + 1, j + 1), the two
// rows first (the CPU's tables interpolate RGBA texels as vectors).
inline vec4 blendRowsFirst(vec4 e00, vec4 e10, vec4 e01, vec4 e11, vec2 t) {
    vec4 bottom = e00 + t.x * (e10 - e00);
    vec4 top = e01 + t.x * (e11 - e01);
    return bottom + t.y * (top - bottom);
}
