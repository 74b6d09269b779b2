#include "stochtex/pattern/fields/fields.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/noise/slopes.h"
#include "stochtex/pattern/fields/field_node.h"

namespace stochtex {

NodeInfo derivativeNode() {
    NodeInfo n{"derivative",
               "linear",
               "Directional derivative of a field, exact on its example (spectral), rescaled about a mean",
               {{"input", PortType::Field, "The field"}},
               PortType::Field,
               {{"angle", ParamType::Number, "Direction, degrees from +u towards +v", 0, -360, 360},
                {"mean", ParamType::Number, "Mean of the result", 0.5, 0, 1},
                {"stddev", ParamType::Number, "Standard deviation of the result", 1.0 / 6.0, 1e-4, 0.5}}};
    n.fold = [](const FieldFold& f) {
        const NoiseExample e = f.linearInput("input");
        const std::array<Image, 2> slopes = spectralSlopes(e.values());
        const double a = f.number("angle") * std::numbers::pi / 180;
        const float c = float(std::cos(a)), s = float(std::sin(a));
        Image d(e.size(), e.size(), 1, Image::Uninitialized{});
        double sumSq = 0;
        for (size_t i = 0; i < d.data().size(); ++i) {
            d.data()[i] = c * slopes[0].data()[i] + s * slopes[1].data()[i];
            sumSq += double(d.data()[i]) * d.data()[i];
        }
        const double rms = std::sqrt(sumSq / double(d.data().size()));
        if (!(rms > 1e-12)) throw InputError(f.where + " (derivative): the input is flat along this direction");
        const float gain = float(f.number("stddev") / rms), mean = float(f.number("mean"));
        for (float& v : d.data()) v = mean + gain * v;
        return NoiseExample(std::move(d));
    };
    // Differentiated on its example: a transform before it would turn the direction.
    n.seenThrough = [](const FieldSight& s) {
        if (!s.input("input").identity())
            throw InputError(s.where + ": its input is seen through a transform of uv; put the transform after the "
                                       "derivative");
        return UvTransform{};
    };
    return n;
}

}  // namespace stochtex
