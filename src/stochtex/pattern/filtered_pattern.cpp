#include "stochtex/pattern/filtered_pattern.h"

#include <cmath>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

namespace {

// H'(x, y) = H(T_x⁻¹(x), T_y⁻¹(y)) on H's own grid.
ColormapTable foldInverseTransforms(const Pattern& p) {
    const ColormapTable& h = p.colormap();
    if (!p.example(0).gaussianized() && !p.example(1).gaussianized()) return h;
    Image t(h.resolutionX(), h.resolutionY(), 3, Image::Uninitialized{});
    for (int j = 0; j < t.height(); ++j)
        for (int i = 0; i < t.width(); ++i) {
            const float x = p.example(0).toOutput(float(i) / float(t.width() - 1));
            const float y = p.example(1).toOutput(float(j) / float(t.height() - 1));
            const Rgb c = h.sample(x, y);
            for (int k = 0; k < 3; ++k) t.at(i, j, k) = c[size_t(k)];
        }
    return ColormapTable(t);
}

// The sky is the pattern's average colour E[H(N)], one colour whatever the
// filter mode: H' convolved exactly (eq. 5, by numerical integration) with
// the Gaussian of the whole example's statistics, in blending space (the
// tiling-and-blending keeps the example's mean and variance), which is
// where every filtered mode's ground converges far away. Neither H at the
// mean (the unfiltered pixel's colour) nor a table's lookup (paper mode's
// stops at σ = 0.125) would be the same colour in every mode.
Rgb averageColour(const Pattern& p, const ColormapTable& blendingSpaceColormap) {
    double mean[2], sigma[2];
    for (int a = 0; a < 2; ++a) {
        const auto& v = p.example(a).values().data();
        double sum = 0, sum2 = 0;
        for (const float x : v) sum += x;
        mean[a] = sum / double(v.size());
        for (const float x : v) sum2 += (x - mean[a]) * (x - mean[a]);
        sigma[a] = std::sqrt(sum2 / double(v.size()));
    }
    return convolveColormapNumerically(blendingSpaceColormap, mean[0], mean[1], sigma[0], sigma[1]);
}

}  // namespace

NamedFilter parseFilter(const std::string& name) { return parseEnum(kFilterNames, name, "filter"); }

std::string filterName(const FilterOptions& options) {
    for (const auto& [name, filter] : kFilterNames)
        if (filter == options.filter()) return name;
    return enumName(kStatisticsSourceNames, options.source) + "/" + enumName(kResponseKindNames, options.response.kind);
}

FilteredPattern::FilteredPattern(const Pattern& pattern, const FilterOptions& options)
    : pattern_(pattern), options_(options), source_(options.source), colormap_(foldInverseTransforms(pattern)) {
    if (options.aniso < 1 || options.aniso > kMaxAnisotropy)
        throw InputError::parameter("aniso", "must be in [1, " + std::to_string(kMaxAnisotropy) + "], got " +
                                                 std::to_string(options.aniso));
    if (options.referenceMaxSamples < 1 || options.referenceMaxSamples > 4096)
        throw InputError::parameter("referenceMaxSamples",
                                    "must be in [1, 4096], got " + std::to_string(options.referenceMaxSamples));
    if (!isPowerOfTwo(pattern.exampleSize()))
        throw InputError("filtering needs power-of-two example sizes (the MIP pyramids halve them); got " +
                         std::to_string(pattern.exampleSize()));
    sky_ = averageColour(pattern, colormap_);
    if (source_ == StatisticsSource::Point) return;  // nothing to prefilter
    response_ = makeResponse(options.response, colormap_);
    // The covariance pyramid only for a shared-offset pair whose response reads it.
    estimator_ = std::make_unique<FootprintEstimator>(
        pattern.tiledField(), pattern.sharedOffsets() && response_->needsCovariance(), options.pack8);
}

const PrefilteredColormap& FilteredPattern::table() const {
    const auto* r = dynamic_cast<const PrefilteredColormapResponse*>(response_.get());
    if (!r) throw std::logic_error("FilteredPattern::table: the response is not a prefiltered colormap");
    return r->table();
}

Footprint FilteredPattern::footprint(double u, double v, const Jacobian& j) const {
    return makeFootprint(u, v, j, estimator_->exampleSize(), estimator_->maxLod(), options_.aniso);
}

Rgb FilteredPattern::shade(const Footprint& f) const { return response_->filtered(estimator_->estimate(f, options_.estimator)); }

Rgb FilteredPattern::shade(bool onPlane, double u, double v, const Jacobian& j) const {
    if (!onPlane) return sky_;
    switch (source_) {
        case StatisticsSource::Point: return pattern_.evaluate(u, v);
        case StatisticsSource::Estimators: return shade(footprint(u, v, j));
        case StatisticsSource::Exact:
            return response_->filtered(
                bruteForceStats(pattern_.tiledField(), u, v, j, options_.referenceMaxSamples));
        case StatisticsSource::Reference: {
            const int n = bruteForceSamples(j, pattern_.exampleSize(), options_.referenceMaxSamples);
            double acc[3] = {0, 0, 0};
            for (int b = 0; b < n; ++b)
                for (int a = 0; a < n; ++a) {
                    const double s = (a + 0.5) / n - 0.5, t = (b + 0.5) / n - 0.5;
                    const Rgb c = pattern_.evaluate(u + s * j.dudx + t * j.dudy, v + s * j.dvdx + t * j.dvdy);
                    for (int k = 0; k < 3; ++k) acc[k] += c[size_t(k)];
                }
            const double inv = 1.0 / (double(n) * n);
            return {float(acc[0] * inv), float(acc[1] * inv), float(acc[2] * inv)};
        }
    }
    return sky_;
}

Image FilteredPattern::render(const Camera& camera, const Progress& progress) const {
    validateCamera(camera);
    if (source_ == StatisticsSource::Point && camera.kind == Camera::Kind::Zoom) return pattern_.render(camera.view);
    Image out(camera.view.width, camera.view.height, 3, Image::Uninitialized{});
    const int w = pattern_.exampleSize();
    // A zoom has one Jacobian for the whole image: build its footprint once.
    const bool oneFootprint = camera.kind == Camera::Kind::Zoom && source_ == StatisticsSource::Estimators;
    Footprint shape;
    if (oneFootprint) {
        double u = 0, v = 0;
        Jacobian j;
        camera.footprint(0, 0, w, u, v, j);
        shape = footprint(0.0, 0.0, j);
    }
    const auto rows = [&](int y0, int y1) {
        for (int py = y0; py < y1; ++py)
            for (int px = 0; px < camera.view.width; ++px) {
                double u = 0, v = 0;
                Jacobian j;
                const bool onPlane = camera.footprint(px, py, w, u, v, j);
                const Rgb c = oneFootprint ? shade(shape.translated(u, v)) : shade(onPlane, u, v, j);
                float* p = out.row(py) + size_t(px) * 3;
                p[0] = c[0];
                p[1] = c[1];
                p[2] = c[2];
            }
    };
    parallelRows(camera.view.height, rows, progress);
    return out;
}

}  // namespace stochtex
