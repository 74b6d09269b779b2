#include "stochtex/pattern/tileable.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

TilePeriod makeTileable(PatternSpec& spec, const ResponseOptions& response, View& view, PartCache* parts) {
    validateView(view);
    TilePeriod t;
    // W of the program the view will render (its first leaf's example).
    t.exampleSize = GraphPattern::build(spec, response, parts).exampleSize();
    const double w = t.exampleSize;
    t.periodsU = std::max(1, int(std::lround(view.width * view.scale / w)));
    view.scale = t.periodsU * w / view.width;
    const double periodsV = view.height * view.scale / w;
    t.periodsV = int(std::lround(periodsV));
    if (t.periodsV < 1 || std::abs(periodsV - t.periodsV) > 1e-9 * periodsV)
        throw InputError::parameter(
            "size",
            "must cover a whole number of example periods along both axes to tile: " + std::to_string(view.width) +
                " × " + std::to_string(view.height) + " pixels at " + formatValue(view.scale) +
                " texels per pixel cover " + std::to_string(t.periodsU) + " × " + formatValue(periodsV) +
                " periods of " + std::to_string(t.exampleSize) + " texels (a square size always tiles)");
    spec.gridPeriods = {t.periodsU, t.periodsV};
    const GridLayout grid = GridLayout::periodic(spec.gridDensity, t.periodsU, t.periodsV);
    t.stretch = grid.densityU / spec.gridDensity;
    validateView(view);
    return t;
}

}  // namespace stochtex
