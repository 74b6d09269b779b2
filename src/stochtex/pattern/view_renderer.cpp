#include "stochtex/pattern/view_renderer.h"

#include <algorithm>
#include <stdexcept>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

// Pixels [first, first + count) of a zoom view along its rows or columns
// as a view of their own: its size `count` along that axis, its offset
// moved by `first` pixels.
Camera partCamera(const Camera& whole, bool rows, int first, int count) {
    if (whole.kind != Camera::Kind::Zoom)
        throw InputError::parameter("camera", std::string(rows ? "bands are rows" : "tiles are columns") +
                                                  " of a zoom view (a plane camera's frame is rendered whole)");
    const std::string what = rows ? "rows" : "columns";
    const int size = rows ? whole.view.height : whole.view.width;
    if (first < 0 || count < 1 || count > size - first)
        throw InputError::parameter(what, what + " " + std::to_string(first) + "–" + std::to_string(first + count) +
                                              " are not inside the view's " + std::to_string(size));
    Camera part = whole;
    (rows ? part.view.height : part.view.width) = count;
    (rows ? part.view.offsetV : part.view.offsetU) += first * whole.view.scale;
    return part;
}

}  // namespace

Camera bandCamera(const Camera& whole, int y0, int rows) { return partCamera(whole, true, y0, rows); }

Camera columnCamera(const Camera& whole, int x0, int columns) { return partCamera(whole, false, x0, columns); }

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
