#pragma once
// The numbers of a pattern file (docs/PATTERNS.md), each described once:
// the parser reads them through these entries (readNumber, readInteger),
// the workbench draws its widgets from them, and the graph node that takes
// the same member (spectral_noise's size, mean and stddev) shares the entry.
// A range changed here changes what files may hold and what the panels
// offer together.
#include "stochtex/pattern/param_info.h"

namespace stochtex {

struct PatternMembers {
    // The pattern.
    ParamInfo scale, gridDensity;
    // A spectrum NOISE.
    ParamInfo noiseSize, noiseMean, noiseStddev;
    // A spectrum component.
    ParamInfo cutoff, frequency, bandwidth, orientation, weight;
    // A COLORMAP, and a painted one's shapes ([x, y] points have coordinate's range each).
    ParamInfo colormapResolution, duty;
    ParamInfo coordinate, radius, inner, outer, width, angle;
    // A normal map.
    ParamInfo amplitude, roughness, specular;
};
// The table, built on first use: the node table copies entries of it,
// perhaps while another file's statics are being initialised (a benchmark
// registering one benchmark per node), so it cannot be a set of globals.
const PatternMembers& patternMembers();

}  // namespace stochtex
