#pragma once
// The numbers of a pattern file (docs/PATTERNS.md), each described once:
// the parser reads them through these entries (readNumber, readInteger),
// the workbench draws its widgets from them, and the graph node that takes
// the same member (spectral_noise's size, mean and stddev) shares the entry.
// A range changed here changes what files may hold and what the panels
// offer together.
#include "stochtex/pattern/param_info.h"

namespace stochtex::pattern_members {

// The pattern.
extern const ParamInfo kScale, kGridDensity;
// A spectrum NOISE.
extern const ParamInfo kNoiseSize, kNoiseMean, kNoiseStddev;
// A spectrum component.
extern const ParamInfo kCutoff, kFrequency, kBandwidth, kOrientation, kWeight;
// A COLORMAP, and a painted one's shapes ([x, y] points have kCoordinate's range each).
extern const ParamInfo kColormapResolution, kDuty;
extern const ParamInfo kCoordinate, kRadius, kInner, kOuter, kWidth, kAngle;
// A normal map.
extern const ParamInfo kAmplitude, kRoughness, kSpecular;

}  // namespace stochtex::pattern_members
