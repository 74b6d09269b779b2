#include "stochtex/pattern/pattern_members.h"

#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex::pattern_members {

using json = nlohmann::json;
constexpr double kMaxFrequency = 1e4;  // cycles per example period; a few hundred are typical
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const ParamInfo kScale{"scale", ParamType::Number, "Example texels per output pixel", 1.0, 1e-6, 1e6, nullptr, {}, 64};
const ParamInfo kGridDensity{"grid_density", ParamType::Number, "Triangle-grid cells per example period",
                             kDefaultGridDensity, 1e-3, 1e3, nullptr, {}, 16};

const ParamInfo kNoiseSize{"size", ParamType::Integer, "Example side, texels (a power of two)", 256, 8, kMaxExampleSize};
const ParamInfo kNoiseMean{"mean", ParamType::Number, "Mean of the example", 0.5, 0, 1};
const ParamInfo kNoiseStddev{"stddev", ParamType::Number, "Standard deviation of the example", 1.0 / 6.0, 1e-4, 0.5};

const ParamInfo kCutoff{"cutoff", ParamType::Number, "A lowpass component's cut-off, cycles per example period",
                        json(), 1e-3, kMaxFrequency, 8.0, {}, 512};
const ParamInfo kFrequency{"frequency", ParamType::Number,
                           "A ring's radius or a bilobe's distance from the origin, cycles per example period", json(),
                           0.0, kMaxFrequency, 12.0, {}, 512};
const ParamInfo kBandwidth{"bandwidth", ParamType::Number, "A ring's or lobe's width, cycles per example period",
                           json(), 1e-3, kMaxFrequency, 3.0, {}, 256};
const ParamInfo kOrientation{"orientation", ParamType::Number, "A bilobe's direction, degrees", 0.0, -360, 360};
const ParamInfo kWeight{"weight", ParamType::Number, "The component's power (the powers of the components add)", 1.0,
                        0.0, 1e6, nullptr, {}, 100};

const ParamInfo kColormapResolution{"resolution", ParamType::Integer, "Table entries per side", 256, 2,
                                    kMaxColormapResolution, nullptr, {}, 1024};
const ParamInfo kDuty{"duty", ParamType::Number, "The part of a period a square profile is high", 0.5, 0, 1};
const ParamInfo kCoordinate{"coordinate", ParamType::Number, "A point's coordinate in the colormap ([0, 1] is the table)",
                            json(), -10, 10, 0.5, {}, kNaN};
const ParamInfo kRadius{"radius", ParamType::Number, "A disc's radius", json(), 0, 10, 0.1, {}, 1};
const ParamInfo kInner{"inner", ParamType::Number, "A ring's inner radius", json(), 0, 10, 0.05, {}, 1};
const ParamInfo kOuter{"outer", ParamType::Number, "A ring's outer radius", json(), 0, 10, 0.1, {}, 1};
const ParamInfo kWidth{"width", ParamType::Number, "A band's width", json(), 0, 10, 0.1, {}, 1};
const ParamInfo kAngle{"angle", ParamType::Number, "A half-plane's or band's direction, degrees", 0.0, -360, 360};

const ParamInfo kAmplitude{"amplitude", ParamType::Number, "RMS slope per axis the height field is scaled to",
                           NormalMapSpec{}.amplitude, 1e-4, 100, nullptr, {}, 4};
const ParamInfo kRoughness{"roughness", ParamType::Number, "Base Beckmann roughness m of each micro-facet",
                           LeanShading{}.roughness, 1e-3, 10, nullptr, {}, 2};
const ParamInfo kSpecular{"specular", ParamType::Number, "Weight of the lobe's reflection", LeanShading{}.specular, 0,
                          1e3, nullptr, {}, 1};

}  // namespace stochtex::pattern_members
