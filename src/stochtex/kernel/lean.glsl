// LEAN mapping of a slope field (Olano & Baker 2010; paper §6.5). Kernel
// file: GLSL and C++, see kernel/glsl.h.
//
// The surface is a height field z(x, y) over the texture plane (x along u,
// y along v, z up); a micro-facet of slopes s = (∂z/∂x, ∂z/∂y) has the
// normal (−s_x, −s_y, 1)/√(1 + |s|²). Over a footprint the slopes have a mean
// b and a 2×2 covariance Σ (paper §4 applied to the slope pair: eq. 9, 14,
// 18). LEAN models the micro-slopes seen through the footprint as the base
// Beckmann lobe of roughness m (slopes ~ N(0, m²/2·I)) spread by that
// distribution: a Gaussian of mean b and covariance Σ + m²/2·I, an
// anisotropic Beckmann lobe. With a zero footprint (Σ = 0) it is the base
// lobe around the point's own slope, the unfiltered shading.

struct LeanLobe {
    vec2 mean;       // mean slope b
    vec3 sigma;      // Σ_xx, Σ_yy, Σ_xy, the base roughness included
    vec3 footprint;  // the footprint's own Σ_xx, Σ_yy, Σ_xy (without the base roughness): the diffuse term's spread
};

// The lobe of a footprint's slope statistics. The estimated covariance can
// leave the positive semi-definite cone (|ĉov| > σ̂_x σ̂_y; the estimators
// are not exact sums): it is clamped back, so that with m > 0 the lobe's
// covariance stays positive definite.
inline LeanLobe leanLobe(vec2 mean, vec2 var, float cov, float roughness) {
    float base = 0.5f * roughness * roughness;
    float vx = max(var.x, 0.0f);
    float vy = max(var.y, 0.0f);
    float bound = sqrt(vx * vy);
    LeanLobe l;
    l.mean = mean;
    l.footprint = vec3(vx, vy, clamp(cov, -bound, bound));
    l.sigma = vec3(vx + base, vy + base, l.footprint.z);
    return l;
}

// The lobe's density of slopes at s (a 2D Gaussian: it integrates to 1
// over the slope plane). exp(−q/2) is written exp2(−q/2·log2 e); one
// division, for 1/det (a pixel's shading is mostly divisions and roots).
inline float leanSlopeDensity(LeanLobe l, vec2 s) {
    float invDet = 1.0f / (l.sigma.x * l.sigma.y - l.sigma.z * l.sigma.z);
    float dx = s.x - l.mean.x;
    float dy = s.y - l.mean.y;
    float q = (dx * dx * l.sigma.y - 2.0f * dx * dy * l.sigma.z + dy * dy * l.sigma.x) * invDet;
    return exp2(-0.72134752f * q) * (0.15915494f * sqrt(invDet));
}

// The micro-facet normal distribution of the lobe at the half vector h
// (h_z > 0, any length): D = P(s_h)/ĥ_z⁴ with s_h = −(h_x, h_y)/h_z, the
// slope whose normal is ĥ = h/|h| (the Jacobian from slopes to directions;
// ∫ D ĥ_z dω = 1). Neither s_h nor 1/ĥ_z² = |h|²/h_z² needs h normalised.
inline float leanNdf(LeanLobe l, vec3 h) {
    float r = 1.0f / h.z;
    vec2 s = vec2(-h.x * r, -h.y * r);
    float secant2 = (h.x * h.x + h.y * h.y + h.z * h.z) * (r * r);
    return leanSlopeDensity(l, s) * (secant2 * secant2);
}

// The Lambertian term of one slope s: n(s)·l = (l_z − s·l_xy)/√(1 + |s|²),
// 0 when the facet faces away.
inline float leanLambert(vec2 s, vec3 l) {
    return max((l.z - s.x * l.x - s.y * l.y) / sqrt(1.0f + s.x * s.x + s.y * s.y), 0.0f);
}

// The Lambertian term averaged over the footprint's slopes s ~ N(b,
// Σ_footprint): five sigma points, b and b ± √3·(L's columns) (L L^T = Σ),
// weights 1/3 and 1/6 each: exact for every polynomial of degree 3 and for
// the fourth powers along L's columns. Lit through the mean normal alone, a
// filtered pixel stayed brighter than the mean of its points' shading at
// every footprint (n·l is concave about the light; a second-order Taylor
// term overshot at RMS slope 0.3). Against Monte Carlo the five points err
// by < 0.001 on average (test LeanLobe.DiffuseQuadrature…); the 3×3
// Gauss–Hermite nodes used before shaded nine times, a quarter of a filtered
// LEAN zoom's render time. With Σ = 0 it is the point's own shading.
inline float leanDiffuse(LeanLobe lobe, vec3 l) {
    vec3 c = lobe.footprint;
    if (c.x <= 0.0f && c.y <= 0.0f) return leanLambert(lobe.mean, l);  // a point: its own shading, exactly
    float l11 = sqrt(c.x);
    float l21 = l11 > 0.0f ? c.z / l11 : 0.0f;
    float l22 = sqrt(max(c.y - l21 * l21, 0.0f));
    vec2 a = vec2(1.73205081f * l11, 1.73205081f * l21);
    vec2 b = vec2(0.0f, 1.73205081f * l22);
    float sides = leanLambert(lobe.mean + a, l) + leanLambert(lobe.mean - a, l) + leanLambert(lobe.mean + b, l) +
                  leanLambert(lobe.mean - b, l);
    return 0.33333333f * leanLambert(lobe.mean, l) + 0.16666667f * sides;
}

// Radiance towards the unit view direction v under a directional light of
// unit direction l (both with z > 0) and unit irradiance: a Lambertian
// albedo averaged over the footprint's normals (leanDiffuse) plus the
// lobe's specular reflection D(h)/(4 v_z) (micro-facet model without
// Fresnel and shadowing; the geometric normal is z), scaled by `specular`.
inline vec3 leanShade(LeanLobe lobe, vec3 l, vec3 v, vec3 albedo, float specular) {
    float d = leanNdf(lobe, l + v);
    return albedo * leanDiffuse(lobe, l) + vec3(specular * d / (4.0f * v.z));
}
