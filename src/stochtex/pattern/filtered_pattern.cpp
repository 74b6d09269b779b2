#include "stochtex/pattern/filtered_pattern.h"

#include <cmath>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"

namespace stochtex {

namespace {

// The sky is the pattern's average colour E[H(N)], one colour whatever the
// filter mode: H' convolved exactly (eq. 5, by numerical integration) with
// the Gaussian of the whole example's statistics, in blending space (the
// tiling-and-blending keeps the example's mean and variance), which is
// where every filtered mode's ground converges far away. Neither H at the
// mean (the unfiltered pixel's colour) nor a table's lookup (paper mode's
// stops at σ = 0.125) would be the same colour in every mode.
Rgb averageColour(const Pattern& p, const ColormapTable& blendingSpaceColormap) {
    const std::array<double, 2> x = exampleMoments(p.example(0)), y = exampleMoments(p.example(1));
    return convolveColormapNumerically(blendingSpaceColormap, x[0], y[0], std::sqrt(x[1]), std::sqrt(y[1]));
}


}  // namespace

FootprintStats fieldStatistics(const TiledField& f) {
    double mean[2] = {0, 0}, m2[3] = {0, 0, 0};
    const auto& x = f.channel(0).example().values().data();
    const auto& y = f.channel(1).example().values().data();
    for (size_t i = 0; i < x.size(); ++i) {
        mean[0] += x[i];
        mean[1] += y[i];
    }
    mean[0] /= double(x.size());
    mean[1] /= double(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
        const double dx = x[i] - mean[0], dy = y[i] - mean[1];
        m2[0] += dx * dx;
        m2[1] += dy * dy;
        m2[2] += dx * dy;
    }
    FootprintStats s;
    s.mean = {float(mean[0]), float(mean[1])};
    s.varX = float(m2[0] / double(x.size()));
    s.varY = float(m2[1] / double(x.size()));
    s.cov = float(m2[2] / double(x.size()));
    return s;
}

std::array<double, 2> exampleMoments(const NoiseExample& example) {
    const auto& v = example.values().data();
    double sum = 0, sum2 = 0;
    for (const float x : v) sum += x;
    const double mean = sum / double(v.size());
    for (const float x : v) sum2 += (x - mean) * (x - mean);
    return {mean, sum2 / double(v.size())};
}

void validateFilterOptions(const FilterOptions& options) {
    if (options.aniso < 1 || options.aniso > kMaxAnisotropy)
        throw InputError::parameter("aniso", "must be in [1, " + std::to_string(kMaxAnisotropy) + "], got " +
                                                 std::to_string(options.aniso));
    if (options.referenceMaxSamples < 1 || options.referenceMaxSamples > 4096)
        throw InputError::parameter("referenceMaxSamples",
                                    "must be in [1, 4096], got " + std::to_string(options.referenceMaxSamples));
}

NamedFilter parseFilter(const std::string& name) { return parseEnum(kFilterNames, name, "filter"); }

std::string filterName(const FilterOptions& options) {
    for (const auto& [name, filter] : kFilterNames)
        if (filter == options.filter()) return name;
    // Another response over a named filter's statistics: "smooth/lean".
    if (options.response.kind != ResponseKind::PrefilteredColormap) {
        const NamedFilter colours{options.source, {ResponseKind::PrefilteredColormap, options.response.prefilter}};
        for (const auto& [name, filter] : kFilterNames)
            if (filter == colours)
                return name + "/" + enumName(kResponseKindNames, options.response.kind) +
                       (options.response.covariance ? "" : " without covariance");
    }
    return enumName(kStatisticsSourceNames, options.source) + "/" + enumName(kResponseKindNames, options.response.kind);
}

FilteredPattern::FilteredPattern(const Pattern& pattern, const FilterOptions& options)
    : pattern_(pattern),
      options_(options),
      source_(options.source),
      field_(&pattern.tiledField()),
      colormap_(foldInverseTransforms(pattern.colormap(), &pattern.example(0), &pattern.example(1))) {
    validateFilterOptions(options);
    if (options.response.kind != ResponseKind::PrefilteredColormap)
        throw InputError::parameter("response", "a pattern's colours are filtered through its prefiltered colormap; "
                                                "the " + enumName(kResponseKindNames, options.response.kind) +
                                                    " response shades a file's normal map, which its program "
                                                    "(GraphPattern::build) carries");
    if (!isPowerOfTwo(field_->exampleSize()))
        throw InputError("filtering needs power-of-two example sizes (the MIP pyramids halve them); got " +
                         std::to_string(field_->exampleSize()));
    sky_ = averageColour(pattern, colormap_);
    if (source_ == StatisticsSource::Point) return;  // nothing to prefilter
    response_ = makeResponse(options.response, colormap_);
    // The covariance pyramid only for a shared-offset pair whose response reads it.
    estimator_ = std::make_unique<FootprintEstimator>(*field_, field_->shared() && response_->needsCovariance(),
                                                      options.pack8);
}

const PrefilteredColormap& FilteredPattern::table() const {
    const auto* r = dynamic_cast<const PrefilteredColormapResponse*>(response_.get());
    if (!r) throw std::logic_error("FilteredPattern::table: the response is not a prefiltered colormap");
    return r->table();
}

Footprint FilteredPattern::footprint(double u, double v, const Jacobian& j) const {
    return makeFootprint(u, v, j, estimator_->exampleSize(), estimator_->maxLod(), options_.aniso);
}

Rgb FilteredPattern::shade(const Footprint& f) const {
    return response_->filtered(estimator_->estimate(f, options_.estimator));
}

Rgb FilteredPattern::shade(bool onPlane, double u, double v, const Jacobian& j) const {
    if (!onPlane) return sky_;
    switch (source_) {
        case StatisticsSource::Point: return pattern_.evaluate(u, v);
        case StatisticsSource::Estimators: return shade(footprint(u, v, j));
        case StatisticsSource::Exact: return response_->filtered(bruteForceStats(*field_, u, v, j, options_.referenceMaxSamples));
        case StatisticsSource::Reference: {
            const int n = bruteForceSamples(j, field_->exampleSize(), options_.referenceMaxSamples);
            return supersampledAverage(u, v, j, n, [&](double pu, double pv) { return pattern_.evaluate(pu, pv); });
        }
    }
    return sky_;
}

Image FilteredPattern::render(const Camera& camera, const Progress& progress) const {
    validateCamera(camera);
    if (source_ == StatisticsSource::Point && camera.kind == Camera::Kind::Zoom)
        return pattern_.render(camera.view);
    Image out(camera.view.width, camera.view.height, 3, Image::Uninitialized{});
    const int w = field_->exampleSize();
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

int FilteredPattern::exampleSize() const { return pattern_.exampleSize(); }

}  // namespace stochtex
