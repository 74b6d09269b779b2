#include "stochtex/image/colour_space.h"

#include "stochtex/core/parallel.h"
#include "stochtex/kernel/colour.h"

namespace stochtex {

float srgbFromLinear(float linear) { return kernel::srgbFromLinear(linear); }
float linearFromSrgb(float code) { return kernel::linearFromSrgb(code); }

namespace {

template <class F>
Image mapValues(const Image& image, F&& f) {
    Image out(image.width(), image.height(), image.channels(), Image::Uninitialized{});
    const size_t rowValues = size_t(image.width()) * size_t(image.channels());
    parallelRows(image.height(), [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* src = image.row(y);
            float* dst = out.row(y);
            for (size_t i = 0; i < rowValues; ++i) dst[i] = f(src[i]);
        }
    });
    return out;
}

}  // namespace

Image srgbFromLinear(const Image& linear) { return mapValues(linear, kernel::srgbFromLinear); }
Image linearFromSrgb(const Image& codes) { return mapValues(codes, kernel::linearFromSrgb); }

Image encodeTransfer(const Image& image, Transfer transfer) {
    return transfer == Transfer::Srgb ? srgbFromLinear(image) : image;
}

Image decodeTransfer(const Image& image, Transfer transfer) {
    return transfer == Transfer::Srgb ? linearFromSrgb(image) : image;
}

}  // namespace stochtex
