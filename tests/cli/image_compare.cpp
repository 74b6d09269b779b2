// For the CLI cases: how far apart two images of one size are, as they are
// and with the second turned upside down (orientation checks).
// Usage: stochtex_image_compare A B
// Prints "mean <m> flipped <f>": mean |Δ| over all pixels and RGB channels,
// in 8-bit steps (1/255); a gray image is compared as RGB of equal channels.
// Exit 0, or 2 when a file cannot be read or the sizes differ.
#include <cmath>
#include <cstdio>
#include <exception>

#include "stochtex/image/image_io.h"

namespace {

double meanAbsDifference(const stochtex::Image& a, const stochtex::Image& b, bool flipB) {
    double sum = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c)
                sum += std::abs(double(a.at(x, y, c)) - b.at(x, flipB ? b.height() - 1 - y : y, c));
    return 255.0 * sum / (3.0 * double(a.width()) * a.height());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: stochtex_image_compare A B\n");
        return 2;
    }
    try {
        const stochtex::Image a = stochtex::toRgb(stochtex::readImage(argv[1]));
        const stochtex::Image b = stochtex::toRgb(stochtex::readImage(argv[2]));
        if (a.width() != b.width() || a.height() != b.height()) {
            std::fprintf(stderr, "stochtex_image_compare: %s and %s differ in size\n", argv[1], argv[2]);
            return 2;
        }
        std::printf("mean %.4f flipped %.4f\n", meanAbsDifference(a, b, false), meanAbsDifference(a, b, true));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stochtex_image_compare: %s\n", e.what());
        return 2;
    }
}
