#pragma once
// Filtered evaluation of a pattern: Ŝ = H̄(μ̂, σ̂) (paper eq. 5–6) and the
// reference S̄ (eq. 3), for any Camera.
//
// Filtering has two axes (pattern/response.h): where the statistics come
// from (FilterOptions::source) and the response that turns them into a
// colour (FilterOptions::response). The named filters of the CLI and the
// papers are shorthands for pairs:
//   none      — point: S = H∘N at the pixel centre (aliases when zoomed out);
//   paper     — estimators + the section-5 prefiltered table;
//   smooth    — estimators + the smooth prefiltered table;
//   exact     — brute-force footprint statistics + the smooth table: isolates
//               the error of the Gaussian approximation (eq. 5) from the
//               error of the estimators (paper Fig. 4b);
//   reference — S̄: the average of H∘N over the footprint parallelogram by an
//               n×n stratified grid, n = clamp(⌈2·extent in texels⌉, 8,
//               referenceMaxSamples) (the response gives only the sky).
// Filtering runs in the blending space: for a Gaussianized exemplar the
// inverse histogram transform is folded into the colormap,
// H'(x, y) = H(T_x⁻¹(x), T_y⁻¹(y)), before prefiltering.
// Sky pixels (plane camera) show the pattern's average, H̄(μ_E, σ_E) (for
// `none`, which builds no table, H at the examples' means).
// The lean response is refused: a file's normal map is its program's
// (GraphPattern::build).
#include <memory>

#include "stochtex/core/enum_names.h"
#include "stochtex/core/progress.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/pattern.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/pattern/response.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

// A named filter: a statistics source and a response.
struct NamedFilter {
    StatisticsSource source = StatisticsSource::Estimators;
    ResponseOptions response;
    bool operator==(const NamedFilter&) const = default;
};
// The one table of filter names (the CLI's --filter, the stability study,
// the bake manifest); each maps a name to a pair.
inline const EnumNames<NamedFilter> kFilterNames{
    {"none", {StatisticsSource::Point, {}}},
    {"paper", {StatisticsSource::Estimators, {ResponseKind::PrefilteredColormap, PrefilterMode::Paper}}},
    {"smooth", {StatisticsSource::Estimators, {ResponseKind::PrefilteredColormap, PrefilterMode::Smooth}}},
    {"exact", {StatisticsSource::Exact, {ResponseKind::PrefilteredColormap, PrefilterMode::Smooth}}},
    {"reference", {StatisticsSource::Reference, {ResponseKind::PrefilteredColormap, PrefilterMode::Smooth}}}};

struct FilterOptions {
    StatisticsSource source = StatisticsSource::Estimators;
    ResponseOptions response;                        // the smooth prefiltered colormap
    int aniso = 1;                                   // K, 1..16
    VarianceEstimator estimator = VarianceEstimator::Paper;
    int referenceMaxSamples = 64;                    // per axis
    bool pack8 = false;                              // 8-bit pyramids (paper §5)

    // Both axes at once, from a named filter.
    FilterOptions& use(const NamedFilter& f) {
        source = f.source;
        response = f.response;
        return *this;
    }
    NamedFilter filter() const { return {source, response}; }
};

// Parses a filter name (kFilterNames); InputError naming `filter` otherwise.
NamedFilter parseFilter(const std::string& name);
// The name of the options' pair; another response over a named filter's
// statistics reads "NAME/RESPONSE" ("smooth/lean", "none/lean without
// covariance"), any other pair "SOURCE/RESPONSE" (e.g.
// "exact/prefiltered-colormap") so that it is never mistaken for a name.
std::string filterName(const FilterOptions& options);

// S̄ (paper eq. 3): the average of pointColour over the footprint
// parallelogram uv + J·(s, t), s, t ∈ [−½, ½], on an n×n grid of cell
// centres. FilteredPattern and FilteredGraph share it.
template <class PointColour>
Rgb supersampledAverage(double u, double v, const Jacobian& j, int n, PointColour&& pointColour) {
    double acc[3] = {0, 0, 0};
    for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
            const double s = (a + 0.5) / n - 0.5, t = (b + 0.5) / n - 0.5;
            const Rgb c = pointColour(u + s * j.dudx + t * j.dudy, v + s * j.dvdx + t * j.dvdy);
            for (int k = 0; k < 3; ++k) acc[k] += c[size_t(k)];
        }
    const double inv = 1.0 / (double(n) * n);
    return {float(acc[0] * inv), float(acc[1] * inv), float(acc[2] * inv)};
}

// InputError naming `aniso` or `referenceMaxSamples` when out of range.
void validateFilterOptions(const FilterOptions& options);
// The mean and variance of an example's values (blending space): those of
// its tiled field, whose tiling and blending keeps them.
std::array<double, 2> exampleMoments(const NoiseExample& example);
// Mean, variances and covariance of a two-channel field over its whole
// period (its examples' own: tiling and blending keeps them), the
// statistics of an infinite footprint.
FootprintStats fieldStatistics(const TiledField& field);

class FilteredPattern final : public ViewRenderer {
public:
    FilteredPattern(const Pattern& pattern, const FilterOptions& options);

    const FilterOptions& options() const { return options_; }
    StatisticsSource source() const { return source_; }
    // Neither is built for the point source.
    const FootprintEstimator& estimator() const { return *estimator_; }
    const Response& response() const { return *response_; }
    // The prefiltered colormap response's table (std::logic_error for
    // another response kind).
    const PrefilteredColormap& table() const;
    // The field whose statistics the response reads: the colour noises.
    const TiledField& field() const { return *field_; }
    // H' (T⁻¹ folded in) that the prefiltered table was built from.
    const ColormapTable& blendingSpaceColormap() const { return colormap_; }

    // The colour of sky pixels (plane camera): the pattern's average colour,
    // the same in every mode.
    const Rgb& skyColour() const { return sky_; }
    // Filtered colour of one footprint (sky = false gives the average colour).
    Rgb shade(bool onPlane, double u, double v, const Jacobian& j) const;
    // progress: the fraction of rows done (may be empty).
    Image render(const Camera& camera, const Progress& progress = {}) const override;
    int exampleSize() const override;

private:
    Footprint footprint(double u, double v, const Jacobian& j) const;
    Rgb shade(const Footprint& f) const;  // estimators
    const Pattern& pattern_;
    FilterOptions options_;
    StatisticsSource source_;
    const TiledField* field_;
    std::unique_ptr<FootprintEstimator> estimator_;
    ColormapTable colormap_;
    std::unique_ptr<Response> response_;
    Rgb sky_{};
};

}  // namespace stochtex
