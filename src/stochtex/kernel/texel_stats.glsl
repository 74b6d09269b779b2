// The statistics of texel footprints that a texel source gives the
// estimators' loop (kernel/estimate.glsl). Kernel file: GLSL and C++, see
// kernel/glsl.h. Apart from the loop so that a GLSL host can declare its
// source's functions, which return these, before the loop that calls them.

struct TexelStats {
    vec2 mean;  // N̂_l of each channel (eq. 8)
    vec2 var;   // σ̂²_l (eq. 12)
    float cov;  // ĉov_l (eq. 17; 0 without covariances)
};

struct ProbeTexels {
    TexelStats lo;  // level l0
    TexelStats hi;  // level l1 (read only when its weight is > 0)
};

// The one texel's statistics as a footprint's (eq. 14–15 reduce to them).
inline FootprintMoments texelMoments(TexelStats t) {
    FootprintMoments r;
    r.mean = t.mean;
    r.var = max(t.var, vec2(0.0f));
    r.cov = t.cov;
    return r;
}

// The Deliot–Heitz baseline: the level's average within-texel statistics
// replace eq. 12 and 17 (the covariance only where the source has one).
inline TexelStats deliotHeitzTexel(TexelStats t, vec3 average, bool hasCovariance) {
    t.var = vec2(average.x, average.y);
    t.cov = hasCovariance ? average.z : 0.0f;
    return t;
}
