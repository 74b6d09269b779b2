#include "stochtex/pattern/view_renderer.h"

#include <algorithm>
#include <stdexcept>

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

Camera columnCamera(const Camera& whole, int x0, int columns) {
    if (whole.kind != Camera::Kind::Zoom)
        throw InputError::parameter("camera",
                                    "tiles are columns of a zoom view (a plane camera's frame is rendered whole)");
    if (x0 < 0 || columns < 1 || columns > whole.view.width - x0)
        throw InputError::parameter("columns", "columns " + std::to_string(x0) + "–" + std::to_string(x0 + columns) +
                                                   " are not inside the view's " + std::to_string(whole.view.width));
    Camera tile = whole;
    tile.view.width = columns;
    tile.view.offsetU = whole.view.offsetU + x0 * whole.view.scale;
    return tile;
}

Image renderRows(const ViewRenderer& renderer, const Camera& whole, int y0, int rows, const Progress& progress) {
    const Camera band = bandCamera(whole, y0, rows);
    const int width = band.view.width;
    if (width <= kMaxOutputSide) return renderer.render(band, progress);
    Image out(width, rows, 3, Image::Uninitialized{});
    for (int x0 = 0; x0 < width; x0 += kMaxOutputSide) {
        const int columns = std::min(kMaxOutputSide, width - x0);
        const Image tile = renderer.render(columnCamera(band, x0, columns),
                                           progressPart(progress, double(x0) / width, double(x0 + columns) / width));
        if (tile.channels() != 3) throw std::logic_error("renderRows: a render is RGB");
        for (int y = 0; y < rows; ++y)
            std::copy_n(tile.data().begin() + size_t(y) * columns * 3, size_t(columns) * 3,
                        out.data().begin() + (size_t(y) * width + x0) * 3);
    }
    return out;
}

int bandRows(int width, int band) {
    if (band < 1) throw InputError::parameter("band", "must be at least 1 row, got " + std::to_string(band));
    if (width < 1) throw InputError::parameter("size", "must be at least 1 pixel wide");
    return int(std::max<long long>(1, std::min<long long>(band, kMaxBandPixels / width)));
}

void renderInBands(const ViewRenderer& renderer, const Camera& whole, int band,
                   const std::function<void(const Image& rows)>& sink, const Progress& progress) {
    const int height = whole.view.height, rowsPerBand = bandRows(whole.view.width, band);
    for (int y0 = 0; y0 < height; y0 += rowsPerBand) {
        const int y1 = std::min(height, y0 + rowsPerBand);
        const std::string rows =
            "rows " + std::to_string(y0) + "–" + std::to_string(y1) + " of " + std::to_string(height);
        sink(renderRows(renderer, whole, y0, y1 - y0,
                        progressPart(progress, double(y0) / height, double(y1) / height, rows)));
    }
}

}  // namespace stochtex
