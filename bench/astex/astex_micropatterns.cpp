// Compiled only with -DSTOCHTEX_ASTEX_DIR (bench/CMakeLists.txt): ASTex's
// own headers, unmodified, from that checkout.
#include "astex_micropatterns.h"

#include <Algo/MicroPatterns/blurred_colorMap.h>
#include <Algo/MicroPatterns/micropatterns.h>
#include <Algo/MicroPatterns/mipmaped_noise.h>
#include <Algo/MicroPatterns/tiling.h>

namespace stochtex::bench {

namespace {

ASTex::ImageGrayd grayImage(const std::vector<float>& values, int size) {
    ASTex::ImageGrayd image;
    image.initItk(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) image.pixelAbsolute(x, y) = values[size_t(y) * size_t(size) + size_t(x)];
    return image;
}

}  // namespace

struct AstexMicroPatterns::Impl {
    ASTex::ImageRGBd colormap;  // BlurredColorMaps keeps a pointer to it
    ASTex::PackedInputNoises noises;
    ASTex::BlurredColorMaps<ASTex::ImageRGBd> colormaps;
    ASTex::ImageRGBd out;

    Impl(const std::vector<float>& a, const std::vector<float>& b, int size, const std::vector<float>& rgb, int side)
        : colormap(rgbImage(rgb, side)), noises(grayImage(a, size), grayImage(b, size)), colormaps(&colormap) {}

    static ASTex::ImageRGBd rgbImage(const std::vector<float>& rgb, int side) {
        ASTex::ImageRGBd image;
        image.initItk(side, side);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const float* p = rgb.data() + 3 * (size_t(y) * size_t(side) + size_t(x));
                image.pixelAbsolute(x, y) = ASTex::ImageRGBd::itkPixel(p[0], p[1], p[2]);
            }
        return image;
    }
};

AstexMicroPatterns::AstexMicroPatterns(const std::vector<float>& noiseA, const std::vector<float>& noiseB, int size,
                                       const std::vector<float>& colormap, int side)
    : impl_(std::make_unique<Impl>(noiseA, noiseB, size, colormap, side)) {}

AstexMicroPatterns::~AstexMicroPatterns() = default;

void AstexMicroPatterns::render(int pixels, double scale) {
    ASTex::Tiling_n_Blendinng tiling;
    ASTex::patterns(impl_->out, pixels, impl_->noises, impl_->colormaps, scale, tiling);
}

std::vector<float> AstexMicroPatterns::image() const {
    const ASTex::ImageRGBd& out = impl_->out;
    std::vector<float> rgb;
    rgb.reserve(size_t(out.width()) * size_t(out.height()) * 3);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const auto& p = out.pixelAbsolute(x, y);
            for (int c = 0; c < 3; ++c) rgb.push_back(float(p[c]));
        }
    return rgb;
}

}  // namespace stochtex::bench
