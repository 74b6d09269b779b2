// The marble texture of the thesis (Tavernier 2017, §2.7.2, eq. 2.29) and
// the noises it is made of (kernel file: GLSL and C++, see kernel/glsl.h):
//
//   I(x) = pattern(a·x + b·noise(x / 2^l)),  l = m + n cos(q x_x) + r t
//
// with pattern(s) = ½ + ½ sin s (bands across a) and noise a gradient noise.
// Letting the scale exponent l vary continuously with x (n ≠ 0) stretches
// the veins; letting it vary with t (r ≠ 0) makes the noise's features slide
// outward from the origin. The fix for both (the thesis's "discontinuities in
// l, blended") reads the noise at the two integer scales around l, each a
// fixed field with its own seed, mixed by fract(l): every field keeps its
// own scale, and at an integer l the mix is continuous because one weight is
// 0. docs/MATH.md "The marble texture" has the derivations.

// Hashed unit gradient of lattice corner c (the angle is uniform, so the
// gradients have no preferred direction).
inline vec2 latticeGradient(ivec2 c, uint seed) {
    float angle = 6.28318531f * unitFloat(pcg3d(uvec3(uint(c.x), uint(c.y), seed)).x);
    return vec2(cos(angle), sin(angle));
}

// Gradient noise (Perlin's, with the quintic fade 6f⁵ − 15f⁴ + 10f³): zero
// at the lattice points, scaled by √2 so that it spans [−1, 1].
inline float gradientNoise(vec2 p, uint seed) {
    vec2 cell = floor(p);
    vec2 f = p - cell;
    ivec2 c = ivec2(int(cell.x), int(cell.y));
    vec2 g00 = latticeGradient(c, seed);
    vec2 g10 = latticeGradient(ivec2(c.x + 1, c.y), seed);
    vec2 g01 = latticeGradient(ivec2(c.x, c.y + 1), seed);
    vec2 g11 = latticeGradient(ivec2(c.x + 1, c.y + 1), seed);
    float n00 = g00.x * f.x + g00.y * f.y;
    float n10 = g10.x * (f.x - 1.0f) + g10.y * f.y;
    float n01 = g01.x * f.x + g01.y * (f.y - 1.0f);
    float n11 = g11.x * (f.x - 1.0f) + g11.y * (f.y - 1.0f);
    vec2 u = f * f * f * (f * (f * 6.0f - 15.0f) + 10.0f);
    float bottom = n00 + u.x * (n10 - n00);
    float top = n01 + u.x * (n11 - n01);
    return 1.41421356f * (bottom + u.y * (top - bottom));
}

// The lattice phase of cellNoise for a seed, in [0, 1)².
inline vec2 cellPhase(uint seed) {
    uvec3 h = pcg3d(uvec3(seed, 0x63656c6cu, 0x70686173u));
    return vec2(unitFloat(h.x), unitFloat(h.y));
}

// White noise constant on each lattice cell, uniform in [−1, 1), the lattice
// shifted by a phase drawn per seed: over seeds two points correlate by the
// chance that they share a cell, ∏ max(0, 1 − |Δp_i|), whatever the points.
// Through the scaling it shows the correlation of the scaling step alone,
// without the gradient noise's own (thesis §2.7.2).
inline float cellNoise(vec2 p, uint seed) {
    vec2 cell = floor(p + cellPhase(seed));
    return 2.0f * unitFloat(pcg3d(uvec3(uint(int(cell.x)), uint(int(cell.y)), seed)).x) - 1.0f;
}

// How the noise follows l (MarbleScaling in textures/marble_texture.h).
const int kMarbleContinuous = 0;         // noise(x / 2^l): the naive form
const int kMarbleBlended = 1;            // the two integer scales around l, mixed by fract(l)
const int kMarbleBlendedCorrected = 2;   // …divided by √((1 − w)² + w²), eq. 2.24 for zero-mean fields

// What a marble evaluation returns (MarbleLayer).
const int kMarbleLayerMarble = 0;       // the texture I(x)
const int kMarbleLayerScaledNoise = 1;  // ½ + ½ noise(x / 2^l): the perturbation alone
const int kMarbleLayerScalingOnly = 2;  // ½ + ½ cellNoise(x / 2^l): the scaling step alone
const int kMarbleLayerBaseNoise = 3;    // ½ + ½ noise(x / 2^m): the noise before any scaling

struct Marble {
    vec2 bandFrequency;  // a, radians per unit of x
    float distortion;    // b, radians per unit of noise
    float level;         // m
    float levelAmplitude;  // n
    float levelFrequency;  // q, radians per unit of x_x
    float levelRate;       // r, per unit of t
    int scaling;           // kMarble{Continuous, Blended, BlendedCorrected}
    uint seed;
};

inline float marbleLevel(Marble m, vec2 x, float t) {
    return m.level + m.levelAmplitude * cos(m.levelFrequency * x.x) + m.levelRate * t;
}

// A field (cell noise if `cells`, else gradient noise) at the scale 2^l.
// Blended: integer scale k reads the field with the seed derived for k, so
// the two fields mixed are independent.
inline float scaledField(Marble m, vec2 x, float level, bool cells) {
    if (m.scaling == kMarbleContinuous) {
        vec2 p = x * exp2(-level);
        return cells ? cellNoise(p, m.seed) : gradientNoise(p, m.seed);
    }
    float k = floor(level);
    float w = level - k;
    vec2 p0 = x * exp2(-k);
    vec2 p1 = p0 * 0.5f;
    uint s0 = deriveSeed(m.seed, uint(int(k)));
    uint s1 = deriveSeed(m.seed, uint(int(k) + 1));
    float v0 = cells ? cellNoise(p0, s0) : gradientNoise(p0, s0);
    float v1 = cells ? cellNoise(p1, s1) : gradientNoise(p1, s1);
    float v = v0 + w * (v1 - v0);
    if (m.scaling == kMarbleBlendedCorrected) v = v / sqrt((1.0f - w) * (1.0f - w) + w * w);
    return v;
}

// One layer of the marble texture at point x and time t, in [0, 1] (the
// corrected blend may leave it, by construction of eq. 2.24).
inline float marbleValue(Marble m, int layer, vec2 x, float t) {
    if (layer == kMarbleLayerBaseNoise) return 0.5f + 0.5f * gradientNoise(x * exp2(-m.level), m.seed);
    float level = marbleLevel(m, x, t);
    if (layer == kMarbleLayerScalingOnly) return 0.5f + 0.5f * scaledField(m, x, level, true);
    float noise = scaledField(m, x, level, false);
    if (layer == kMarbleLayerScaledNoise) return 0.5f + 0.5f * noise;
    float s = m.bandFrequency.x * x.x + m.bandFrequency.y * x.y + m.distortion * noise;
    return 0.5f + 0.5f * sin(s);
}
