#include "stochtex/textures/texture_source.h"

#include <cmath>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

std::span<const OptionMember<ZoomBase>> zoomBaseMembers() {
    static const OptionMember<ZoomBase> members[] = {
        {"baseSize", "Period of the white-noise lattice", 2, 16384, &ZoomBase::size},
    };
    return members;
}

void validateZoomBase(const ZoomBase& base) {
    if (base.image.empty()) checkMembers(base, zoomBaseMembers());
}

ZoomSource::ZoomSource(const ZoomParams& params, ZoomBase base) : params_(params), base_(std::move(base)) {
    validateZoomParams(params_);
    validateZoomBase(base_);
    first_ = lattice(0);
}

LatticeTexture ZoomSource::lattice(int instance) const {
    if (!base_.image.empty()) {
        const Image gray = toGray(base_.image);
        const auto o = imageInstanceOffset(instance, gray.width(), gray.height());
        return LatticeTexture::fromImage(instance == 0 ? gray : shiftedPeriodic(gray, o[0], o[1]));
    }
    return LatticeTexture::whiteNoise(base_.size, base_.size, deriveSeed(base_.seed, uint32_t(instance)));
}

Image ZoomSource::render(const SourceRegion& region, double time, int instance) const {
    ZoomParams p = params_;
    p.time = time;
    const ZoomRegion r{region.width, region.height, region.x0, region.y0};
    return renderZoom(instance == 0 ? first_ : lattice(instance), p, r);
}

std::unique_ptr<const AnalyticStatistics> ZoomSource::statistics(double time) const {
    ZoomParams p = params_;
    p.time = time;
    return std::make_unique<ZoomAnalyticStatistics>(p, first_);
}

std::array<int, 2> imageInstanceOffset(int instance, int width, int height) {
    if (instance == 0 || width < 1 || height < 1) return {0, 0};
    const UInt3 h = pcg3d({uint32_t(instance), 0x1ba6eu, 0x5e1f7u});
    return {int(h.x % uint32_t(width)), int(h.y % uint32_t(height))};
}

ImageTextureSource::ImageTextureSource(Image gray) : image_(std::move(gray)) { LatticeTexture::checkImage(image_); }

Image ImageTextureSource::render(const SourceRegion& region, double, int instance) const {
    const int w = image_.width(), h = image_.height();
    const auto o = imageInstanceOffset(instance, w, h);
    Image out(region.width, region.height, 1, Image::Uninitialized{});
    const auto wrap = [](long long v, int n) { return int(((v % n) + n) % n); };
    for (int y = 0; y < region.height; ++y) {
        const int ty = wrap((long long)std::floor(region.y0) + y + o[1], h);
        for (int x = 0; x < region.width; ++x)
            out.at(x, y) = image_.at(wrap((long long)std::floor(region.x0) + x + o[0], w), ty);
    }
    return out;
}

std::array<double, 2> instanceOffset(int instance, int exampleSize) {
    if (instance == 0) return {0.0, 0.0};
    // Whole texels up to 1024 periods: far enough for a new set of tile
    // offsets, near enough that double uv keeps every fraction of a texel.
    const UInt3 h = pcg3d({uint32_t(instance), 0x5eedu, 0x0ff5e7u});
    const uint32_t range = 1024u * uint32_t(exampleSize);
    return {double(h.x % range), double(h.y % range)};
}

namespace {

// The view of `base` moved to the region and to the instance's window.
View windowView(View base, const SourceRegion& region, int instance, int exampleSize) {
    const auto o = instanceOffset(instance, exampleSize);
    base.width = region.width;
    base.height = region.height;
    base.offsetU += region.x0 * base.scale + o[0];
    base.offsetV += region.y0 * base.scale + o[1];
    return base;
}

}  // namespace

Image CameraSource::render(const SourceRegion& region, double time, int instance) const {
    checkWindow(region, time);
    Camera c = camera_;
    if (c.kind == Camera::Kind::Plane) {
        const auto o = instanceOffset(instance, exampleSize_);
        c.view.width = region.width;
        c.view.height = region.height;
        c.view.offsetU += o[0];
        c.view.offsetV += o[1];
    } else {
        c.view = windowView(c.view, region, instance, exampleSize_);
    }
    return renderer_.render(c);
}

void CameraSource::checkWindow(const SourceRegion& region, double) const {
    // A perspective frame is not translation invariant: only whole frames.
    if (camera_.kind == Camera::Kind::Plane && (region.x0 != 0 || region.y0 != 0))
        throw InputError("pattern source: a plane camera renders whole frames (region offset must be 0)");
}

PhasorNoiseSource::PhasorNoiseSource(const PhasorNoiseParams& params, ColormapTable colormap, const View& view,
                                     int exampleSize)
    : noise_(params), colormap_(std::move(colormap)), view_(view), exampleSize_(exampleSize) {
    if (exampleSize < 1) throw std::invalid_argument("PhasorNoiseSource: exampleSize must be positive");
}

Image PhasorNoiseSource::render(const SourceRegion& region, double, int instance) const {
    PhasorNoiseParams p = noise_.params();
    if (instance != 0) p.seed = deriveSeed(p.seed, uint32_t(instance));
    const PhasorNoise noise(p);
    View view = view_;
    view.offsetU += region.x0 * view.scale;
    view.offsetV += region.y0 * view.scale;
    const double invW = 1.0 / double(exampleSize_);
    Image out(region.width, region.height, 3, Image::Uninitialized{});
    parallelRows(region.height, [&](int y0, int y1) {
        for (int py = y0; py < y1; ++py) {
            for (int px = 0; px < region.width; ++px) {
                const auto [u, v] = pixelUv(view, invW, px, py);
                const double phase = noise.phase(u, v);
                const Rgb c =
                    colormap_.sample(float(0.5 + 0.25 * std::cos(phase)), float(0.5 + 0.25 * std::sin(phase)));
                for (int k = 0; k < 3; ++k) out.at(px, py, k) = c[size_t(k)];
            }
        }
    });
    return out;
}

ImageSequenceSource::ImageSequenceSource(std::vector<Image> frames) : frames_(std::move(frames)) {
    if (frames_.empty()) throw InputError("image sequence: no image");
    for (size_t k = 1; k < frames_.size(); ++k)
        if (frames_[k].width() != width() || frames_[k].height() != height() || frames_[k].channels() != channels())
            throw InputError("image sequence: image " + std::to_string(k + 1) + " is " +
                             std::to_string(frames_[k].width()) + "×" + std::to_string(frames_[k].height()) + "×" +
                             std::to_string(frames_[k].channels()) + ", the first is " + std::to_string(width()) + "×" +
                             std::to_string(height()) + "×" + std::to_string(channels()));
}

void ImageSequenceSource::checkWindow(const SourceRegion& region, double time) const {
    if (!(std::isfinite(time) && time >= 0 && time < frames()))
        throw InputError::parameter("time", "must be in [0, " + std::to_string(frames()) +
                                                ") for an image sequence (image k at time k), got " +
                                                formatValue(time));
    const int x0 = int(std::lround(region.x0)), y0 = int(std::lround(region.y0));
    if (x0 < 0 || y0 < 0 || region.width < 1 || region.height < 1 || x0 + region.width > width() ||
        y0 + region.height > height())
        throw InputError::parameter("size", "of the window, " + std::to_string(region.width) + "x" +
                                                std::to_string(region.height) + " at (" + std::to_string(x0) + ", " +
                                                std::to_string(y0) + "), is not inside the " + std::to_string(width()) +
                                                "x" + std::to_string(height()) + " images");
}

void ImageSequenceSource::checkInstances(int count) const {
    if (count > frames())
        throw InputError::parameter("instances", "must be at most " + std::to_string(frames()) +
                                                     " (instance i reads image i), got " + std::to_string(count));
}

Image ImageSequenceSource::render(const SourceRegion& region, double time, int instance) const {
    checkWindow(region, instance != 0 ? 0.0 : time);
    if (instance < 0) throw InputError::parameter("instances", "must be ≥ 0, got " + std::to_string(instance));
    checkInstances(instance + 1);
    const Image& f = frames_[size_t(instance != 0 ? instance : int(std::floor(time)))];
    const int x0 = int(std::lround(region.x0)), y0 = int(std::lround(region.y0));
    if (x0 == 0 && y0 == 0 && region.width == f.width() && region.height == f.height()) return f;
    Image out(region.width, region.height, f.channels());
    for (int y = 0; y < region.height; ++y)
        for (int x = 0; x < region.width; ++x)
            for (int c = 0; c < f.channels(); ++c) out.at(x, y, c) = f.at(x0 + x, y0 + y, c);
    return out;
}

}  // namespace stochtex
