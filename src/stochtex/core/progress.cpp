#include "stochtex/core/progress.h"

#include <memory>

namespace stochtex {

Progress progressPart(const Progress& parent, double from, double to, const std::string& name) {
    if (!parent) return {};
    // The part's name is shown from its first report on; later unnamed
    // reports keep whatever step the part last named.
    auto named = std::make_shared<bool>(false);
    return [parent, from, to, name, named](double fraction, const std::string& step) {
        std::string shown;
        if (!step.empty())
            shown = name.empty() ? step : name + ": " + step;
        else if (!*named)
            shown = name;
        *named = *named || !shown.empty();
        parent(from + fraction * (to - from), shown);
    };
}

Progress progressPart(const Progress& parent, int index, int count, const std::string& name) {
    return progressPart(parent, double(index) / count, double(index + 1) / count, name);
}

}  // namespace stochtex
