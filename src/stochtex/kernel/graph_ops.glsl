// What the ops of texture graphs share (pattern/ops/op_host.h; kernel file:
// GLSL and C++, see kernel/glsl.h): reading a colour as a field and the
// moments of a field-valued table. Each op's own formula is its file in
// pattern/ops/.
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
