// The footprint estimators' sums (paper §4). Kernel file: GLSL and C++, see
// kernel/glsl.h.
//
// Given each texel footprint's N̂_l, σ̂²_l, ĉov_l (eq. 8, 12, 17:
// blendMean and blendVariance in kernel/grid.glsl), a footprint made of
// weighted texel footprints (probes × two levels) has
//   μ̂ = Σ w_P N̂,  σ̂² = Σ w_P (N̂² + σ̂²_l) − μ̂²,  ĉov = Σ w_P (N̂ N̂' + ĉov_l) − μ̂ μ̂'
// (eq. 9, 14–15, 18–19). The sums are taken about the first texel's mean
// (the shift), so that the final subtraction does not cancel in float.

struct Moments {
    vec2 shift;  // the first texel's mean
    vec2 m;      // Σ w_P (N̂ − shift)
    vec2 m2;     // Σ w_P ((N̂ − shift)² + σ̂²_l)
    float mxy;   // Σ w_P ((N̂_x − shift_x)(N̂_y − shift_y) + ĉov_l)
};

inline Moments momentsAbout(vec2 shift) {
    Moments a;
    a.shift = shift;
    a.m = vec2(0.0f);
    a.m2 = vec2(0.0f);
    a.mxy = 0.0f;
    return a;
}

inline Moments momentsAdd(Moments a, float weight, vec2 mean, vec2 var, float cov) {
    vec2 d = mean - a.shift;
    a.m = a.m + weight * d;
    a.m2 = a.m2 + weight * (d * d + var);
    a.mxy = a.mxy + weight * (d.x * d.y + cov);
    return a;
}

// Mean, variances (clamped at 0) and covariance of N over a footprint.
struct FootprintMoments {
    vec2 mean;
    vec2 var;
    float cov;
};

inline FootprintMoments momentsResult(Moments a) {
    FootprintMoments r;
    r.mean = a.shift + a.m;
    r.var = max(a.m2 - a.m * a.m, vec2(0.0f));
    r.cov = a.mxy - a.m.x * a.m.y;
    return r;
}
