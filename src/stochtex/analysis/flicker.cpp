#include "stochtex/analysis/flicker.h"

#include <limits>

#include "stochtex/analysis/optical_flow.h"

namespace stochtex {

FlickerMeasure flowCompensatedFlicker(const Image& previous, const Image& next, Image* residualMap) {
    const Image a = toGray(previous), b = toGray(next);
    const Image flow = denseFlow(previous, next, FlowMethod::Dis);  // checks the sizes
    FlickerMeasure m;
    m.residual = warpedDifference(
        a, b, [&](int x, int y) { return std::array<double, 2>{x + flow.at(x, y, 0), y + flow.at(x, y, 1)}; },
        residualMap);
    m.contrast = 0.5 * (channelStats(a).stddev + channelStats(b).stddev);
    m.relative = relativeFlicker(m.residual, m.contrast);
    return m;
}

double relativeFlicker(double residual, double contrast) {
    return contrast > 1e-3 ? residual / contrast : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace stochtex
