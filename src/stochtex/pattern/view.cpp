#include "stochtex/pattern/view.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/pattern/param_info.h"

namespace stochtex {

const ParamInfo& viewScaleParam() {
    static const ParamInfo p = optionParam("scale", ParamType::Number, "Example texels per output pixel", 1.0,
                                           kMinViewScale, kMaxViewScale, "scale");
    return p;
}

void validateView(const View& view, ViewUse use) {
    const std::string size = std::to_string(view.width) + "x" + std::to_string(view.height);
    // A baked view is rendered a band of tiles at a time: its sides grow to the image files' cap.
    const int maxSide = use == ViewUse::BandedBake ? kMaxBakedSide : kMaxOutputSide;
    if (view.width < 1 || view.height < 1 || view.width > maxSide || view.height > maxSide)
        throw InputError::parameter("size", "must be in [1, " + std::to_string(maxSide) + "] per side, got " + size);
    if (use == ViewUse::Render && (long long)view.width * view.height > kMaxOutputPixels)
        throw InputError::parameter("size",
                                    "must be at most " + std::to_string(kMaxOutputPixels) + " pixels, got " + size);
    checkNumber(viewScaleParam(), view.scale);
    if (!std::isfinite(view.offsetU) || !std::isfinite(view.offsetV) || std::abs(view.offsetU) > 1e9 ||
        std::abs(view.offsetV) > 1e9)
        throw InputError::parameter("offset", "must be finite and at most 1e9 texels, got " +
                                                  formatValue(view.offsetU) + "," + formatValue(view.offsetV));
}

}  // namespace stochtex
