// The per-pixel operations of texture-graph nodes past the linear part
// (pattern/graph_pattern.h; kernel file: GLSL and C++, see kernel/glsl.h).
// The linear nodes fold into the examples the graph's leaves are tiled
// from; what remains is a short program of these operations per pixel.
//
// Unfiltered, a value flowing along an edge is a colour (vec3) or a field
// (a float). Filtered, a field is carried by its footprint moments,
// vec2(mean, variance), and a colour by its mean: an operation then maps
// moments to moments. Tables (the 2D transfer functions and 1D curves)
// store, for a field-valued node, the field g and its square per entry, so
// that one lookup of the prefiltered table, [T ∗ G_σ](μ), gives E[g] and
// E[g²] under the Gaussian of the input's moments (docs/MATH.md, "Filtering
// a graph by moment matching").

const int kGraphChannelRed = 0;
const int kGraphChannelGreen = 1;
const int kGraphChannelBlue = 2;
const int kGraphChannelLuminance = 3;  // Rec. 709 luminance of linear RGB

// The field a colour gives: one of its channels or its luminance.
inline float graphChannel(vec3 c, int channel) {
    if (channel == kGraphChannelLuminance) return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
    return channel == kGraphChannelRed ? c.x : (channel == kGraphChannelGreen ? c.y : c.z);
}

// A field-valued table's entry: the field and its square.
inline vec3 momentEntry(float g) { return vec3(g, g * g, 0.0f); }

// Moment matching: a field's mean and variance from a prefiltered lookup of
// its (g, g²) table. E[g²] − E[g]² is clamped at 0, where rounding in a
// flat region of g could make it negative.
inline vec2 matchedMoments(vec3 lookup) { return vec2(lookup.x, max(lookup.y - lookup.x * lookup.x, 0.0f)); }

// The standard deviation a prefiltered lookup reads from a field's moments
// (mean, variance): the variance is clamped at 0, where an estimator's
// rounding leaves it slightly negative.
inline float momentSigma(vec2 m) { return sqrt(max(m.y, 0.0f)); }

// affine node: scale·x + offset, on a value and on moments (exact).
inline float affineValue(float x, float scale, float offset) { return scale * x + offset; }
inline vec2 affineMoments(vec2 m, float scale, float offset) {
    return vec2(scale * m.x + offset, scale * scale * m.y);
}

// sum node: w_a·a + w_b·b, on values and on moments. The moments' variance
// takes the two inputs as uncorrelated over the footprint, which holds for
// fields from different sources and not for two functions of one source
// (their covariance is not tracked).
inline float sumValue(float a, float b, float wa, float wb) { return wa * a + wb * b; }
inline vec2 sumMoments(vec2 a, vec2 b, float wa, float wb) {
    return vec2(wa * a.x + wb * b.x, wa * wa * a.y + wb * wb * b.y);
}

// mix node: a + t·(b − a), t not clamped. It is linear in each of a, b and
// t, so on means it is the same formula, exact when t is uncorrelated with
// the colours over the footprint (put a curve before t to clamp it).
inline vec3 mixColour(vec3 a, vec3 b, float t) { return a + t * (b - a); }

// compose node: a colour from three fields. On means it is the same
// formula, exact (a colour's mean is its channels' means).
inline vec3 composeColour(float r, float g, float b) { return vec3(r, g, b); }

// lean node: the radiance of a height field's micro-facets (kernel/lean.glsl,
// paper §6.5). The slopes' footprint mean, variances and covariance make
// the anisotropic Beckmann lobe; unfiltered, the variances and covariance
// are 0 (the base lobe about the point's slope). albedo is a colour input's
// value, or its footprint mean when filtered: exact when the albedo is
// uncorrelated with the slopes over the footprint.
inline vec3 leanNodeShade(vec2 slopeMean, vec2 slopeVar, float slopeCov, vec3 albedo, vec3 light, vec3 eye,
                          float roughness, float specular) {
    return leanShade(leanLobe(slopeMean, slopeVar, slopeCov, roughness), light, eye, albedo, specular);
}
