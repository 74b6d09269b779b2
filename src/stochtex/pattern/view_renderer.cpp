#include "stochtex/pattern/view_renderer.h"

#include <algorithm>

#include "stochtex/core/error.h"

namespace stochtex {

Camera bandCamera(const Camera& whole, int y0, int rows) {
    if (whole.kind != Camera::Kind::Zoom)
        throw InputError::parameter("camera",
                                    "bands are rows of a zoom view (a plane camera's frame is rendered whole)");
    if (y0 < 0 || rows < 1 || rows > whole.view.height - y0)
        throw InputError::parameter("rows", "rows " + std::to_string(y0) + "–" + std::to_string(y0 + rows) +
                                                " are not inside the view's " + std::to_string(whole.view.height));
    Camera band = whole;
    band.view.height = rows;
    band.view.offsetV = whole.view.offsetV + y0 * whole.view.scale;
    return band;
}

void renderInBands(const ViewRenderer& renderer, const Camera& whole, int band,
                   const std::function<void(const Image& rows)>& sink, const Progress& progress) {
    if (band < 1) throw InputError::parameter("band", "must be at least 1 row, got " + std::to_string(band));
    const int height = whole.view.height;
    for (int y0 = 0; y0 < height; y0 += band) {
        const int y1 = std::min(height, y0 + band);
        const std::string rows =
            "rows " + std::to_string(y0) + "–" + std::to_string(y1) + " of " + std::to_string(height);
        sink(renderer.render(bandCamera(whole, y0, y1 - y0),
                             progressPart(progress, double(y0) / height, double(y1) / height, rows)));
    }
}

}  // namespace stochtex
