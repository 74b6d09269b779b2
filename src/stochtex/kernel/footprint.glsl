// Pixel footprints as anisotropic probes (paper eq. 9, 15; the OpenGL
// anisotropic filtering description, EXT_texture_filter_anisotropic).
// Kernel file: GLSL and C++, see kernel/glsl.h.
//
// With P_x = W‖∂uv/∂x‖ and P_y = W‖∂uv/∂y‖ in texels: N = min(⌈P_max/P_min⌉,
// K) probes (1 when K = 1) spread along the major axis at
// ((k + ½)/N − ½)·axis, each with λ = log2(P_max/N) clamped to [0, L] and
// weight 1/N; each probe is split between levels ⌊λ⌋ and ⌊λ⌋ + 1.

const int kMaxAnisotropy = 16;
// A whole-number ratio P_max/P_min computed in float may come out a few ulps
// above the integer; ⌈ratio − slack⌉ keeps it from costing one more probe.
const float kAnisoRatioSlack = 1e-6f;

// log2 x (x > 0) whose integer part comes from the exponent field, exactly:
// only the mantissa goes through log2, which GPUs approximate.
inline float log2Split(float x) {
    uint bits = floatBitsToUint(x);
    int e = int(bits >> 23u) - 127;
    float m = uintBitsToFloat((bits & 0x007fffffu) | 0x3f800000u);
    return float(e) + log2(m);
}

struct ProbeLayout {
    int count;  // N ∈ [1, K]
    float lod;  // λ of every probe, in [0, maxLod]
    vec2 axis;  // the major axis of the footprint (uv per pixel)
};

// jx, jy: the Jacobian's columns ∂uv/∂x, ∂uv/∂y; texels = W; maxAniso = K.
inline ProbeLayout probeLayout(vec2 jx, vec2 jy, float texels, int maxAniso, int maxLod) {
    float px = texels * length(jx);
    float py = texels * length(jy);
    bool xMajor = px >= py;
    float pmax = max(px, py);
    float pmin = min(px, py);
    int n = 1;
    if (maxAniso > 1 && pmin > 0.0f) n = int(min(ceil(pmax / pmin - kAnisoRatioSlack), float(maxAniso)));
    else if (maxAniso > 1 && pmax > 0.0f) n = maxAniso;  // degenerate (a line): as anisotropic as allowed
    n = clamp(n, 1, max(maxAniso, 1));
    float rho = pmax / float(n);
    ProbeLayout p;
    p.count = n;
    p.lod = rho > 0.0f ? clamp(log2Split(rho), 0.0f, float(maxLod)) : 0.0f;
    p.axis = xMajor ? jx : jy;
    return p;
}

// Where probe k sits along the axis, in units of the axis: t ∈ (−½, ½).
inline float probePosition(int k, int count) {
    return count == 1 ? 0.0f : (float(k) + 0.5f) / float(count) - 0.5f;
}

// The two pyramid levels a probe reads (trilinear) and the weight of each
// texel footprint (probe weight 1/N times the level's share).
struct ProbeLevels {
    int l0;
    int l1;
    float frac;  // share of l1
    float w0;
    float w1;
};

inline ProbeLevels probeLevels(float lod, int maxLod, int count) {
    ProbeLevels p;
    p.l0 = min(int(lod), maxLod);
    p.l1 = min(p.l0 + 1, maxLod);
    p.frac = lod - float(p.l0);
    p.w0 = (1.0f - p.frac) / float(count);
    p.w1 = p.frac / float(count);
    return p;
}

// One probe at a whole level (every magnified pixel, or λ clamped at the
// top): eq. 14–15 reduce to the texel's own statistics.
inline bool isSingleTexel(int count, float frac) {
    return count == 1 && frac == 0.0f;
}
