#include "stochtex/pattern/pattern_members.h"

#include <limits>

#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/pattern_file.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

const PatternMembers& patternMembers() {
    using json = nlohmann::json;
    constexpr double kMaxFrequency = 1e4;  // cycles per example period; a few hundred are typical
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    static const PatternMembers members = [&] {
        PatternMembers m;
        m.scale = viewScaleParam();
        m.scale.dragMax = 64;
        m.gridDensity = ParamInfo{"grid_density",
                                  ParamType::Number,
                                  "Triangle-grid cells per example period",
                                  kDefaultGridDensity,
                                  1e-3,
                                  1e3,
                                  nullptr,
                                  {},
                                  16};
        m.noiseSize =
            ParamInfo{"size", ParamType::Integer, "Example side, texels (a power of two)", 256, 8, kMaxExampleSize};
        m.noiseMean = ParamInfo{"mean", ParamType::Number, "Mean of the example", 0.5, 0, 1};
        m.noiseStddev =
            ParamInfo{"stddev", ParamType::Number, "Standard deviation of the example", 1.0 / 6.0, 1e-4, 0.5};
        m.cutoff = ParamInfo{"cutoff",
                             ParamType::Number,
                             "A lowpass component's cut-off, cycles per example period",
                             json(),
                             1e-3,
                             kMaxFrequency,
                             8.0,
                             {},
                             512};
        m.frequency = ParamInfo{"frequency",
                                ParamType::Number,
                                "A ring's radius or a bilobe's distance from the origin, cycles per example period",
                                json(),
                                0.0,
                                kMaxFrequency,
                                12.0,
                                {},
                                512};
        m.bandwidth = ParamInfo{"bandwidth",
                                ParamType::Number,
                                "A ring's or lobe's width, cycles per example period",
                                json(),
                                1e-3,
                                kMaxFrequency,
                                3.0,
                                {},
                                256};
        m.orientation = ParamInfo{"orientation", ParamType::Number, "A bilobe's direction, degrees", 0.0, -360, 360};
        m.weight = ParamInfo{"weight",
                             ParamType::Number,
                             "The component's power (the powers of the components add)",
                             1.0,
                             0.0,
                             1e6,
                             nullptr,
                             {},
                             100};
        m.colormapResolution = ParamInfo{
            "resolution", ParamType::Integer, "Table entries per side", 256, 2, kMaxColormapResolution, nullptr, {},
            1024};
        m.colormapResolution.flag = "resolution";  // `colormap --resolution`
        m.duty = ParamInfo{"duty", ParamType::Number, "The part of a period a square profile is high", 0.5, 0, 1};
        m.coordinate = ParamInfo{"coordinate",
                                 ParamType::Number,
                                 "A point's coordinate in the colormap ([0, 1] is the table)",
                                 json(),
                                 -10,
                                 10,
                                 0.5,
                                 {},
                                 kNaN};
        m.radius = ParamInfo{"radius", ParamType::Number, "A disc's radius", json(), 0, 10, 0.1, {}, 1};
        m.inner = ParamInfo{"inner", ParamType::Number, "A ring's inner radius", json(), 0, 10, 0.05, {}, 1};
        m.outer = ParamInfo{"outer", ParamType::Number, "A ring's outer radius", json(), 0, 10, 0.1, {}, 1};
        m.width = ParamInfo{"width", ParamType::Number, "A band's width", json(), 0, 10, 0.1, {}, 1};
        m.angle = ParamInfo{"angle", ParamType::Number, "A half-plane's or band's direction, degrees", 0.0, -360, 360};
        m.amplitude = ParamInfo{"amplitude",
                                ParamType::Number,
                                "RMS slope per axis the height field is scaled to",
                                NormalMapSpec{}.amplitude,
                                1e-4,
                                100,
                                nullptr,
                                {},
                                4};
        m.roughness = ParamInfo{"roughness",
                                ParamType::Number,
                                "Base Beckmann roughness m of each micro-facet",
                                LeanShading{}.roughness,
                                1e-3,
                                10,
                                nullptr,
                                {},
                                2};
        m.specular = ParamInfo{"specular",
                               ParamType::Number,
                               "Weight of the lobe's reflection",
                               LeanShading{}.specular,
                               0,
                               1e3,
                               nullptr,
                               {},
                               1};
        return m;
    }();
    return members;
}

}  // namespace stochtex
