#pragma once
// Filtered evaluation of a pattern: Ŝ = H̄(μ̂, σ̂) (paper eq. 5–6) and the
// reference S̄ (eq. 3), for any Camera.
//
// Modes:
//   none      — S = H∘N at the pixel centre (aliases when zoomed out);
//   paper     — footprint estimators + the section-5 prefiltered table;
//   smooth    — footprint estimators + the smooth prefiltered table;
//   exact     — brute-force footprint statistics + the smooth table: isolates
//               the error of the Gaussian approximation (eq. 5) from the
//               error of the estimators (paper Fig. 4b);
//   reference — S̄: the average of H∘N over the footprint parallelogram by an
//               n×n stratified grid, n = clamp(⌈2·extent in texels⌉, 8,
//               referenceMaxSamples).
// Filtering runs in the blending space: for a Gaussianized exemplar the
// inverse histogram transform is folded into the colormap,
// H'(x, y) = H(T_x⁻¹(x), T_y⁻¹(y)), before prefiltering.
// Sky pixels (plane camera) show the pattern's average, H̄(μ_E, σ_E) (for
// `none`, which builds no table, H at the examples' means).
#include <memory>

#include "stochtex/core/enum_names.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/pattern.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/pattern/response.h"

namespace stochtex {

// The named filters of the CLI and the papers: each is a statistics source
// and a response (pattern/response.h).
enum class FilterMode { None, Paper, Smooth, Exact, Reference };
StatisticsSource statisticsSource(FilterMode mode);
// The prefiltered table's mode (None and Reference build no table).
PrefilterMode prefilterMode(FilterMode mode);
inline const EnumNames<FilterMode> kFilterModeNames{{"none", FilterMode::None},
                                                    {"paper", FilterMode::Paper},
                                                    {"smooth", FilterMode::Smooth},
                                                    {"exact", FilterMode::Exact},
                                                    {"reference", FilterMode::Reference}};

struct FilterOptions {
    FilterMode mode = FilterMode::Smooth;
    int aniso = 1;                                   // K, 1..16
    VarianceEstimator estimator = VarianceEstimator::Paper;
    int referenceMaxSamples = 64;                    // per axis
    bool pack8 = false;                              // 8-bit pyramids (paper §5)
};

class FilteredPattern {
public:
    FilteredPattern(const Pattern& pattern, const FilterOptions& options);

    const FilterOptions& options() const { return options_; }
    StatisticsSource source() const { return source_; }
    // Not built for FilterMode::None.
    const FootprintEstimator& estimator() const { return *estimator_; }
    const Response& response() const { return *response_; }
    const PrefilteredColormap& table() const { return response_->table(); }
    // H' (T⁻¹ folded in) that the prefiltered table was built from.
    const ColormapTable& blendingSpaceColormap() const { return colormap_; }

    // The colour of sky pixels (plane camera): the pattern's average colour,
    // the same in every mode.
    const Rgb& skyColour() const { return sky_; }
    // Filtered colour of one footprint (sky = false gives the average colour).
    Rgb shade(bool onPlane, double u, double v, const Jacobian& j) const;
    Image render(const Camera& camera) const;

private:
    Footprint footprint(double u, double v, const Jacobian& j) const;
    Rgb shade(const Footprint& f) const;  // estimators
    const Pattern& pattern_;
    FilterOptions options_;
    StatisticsSource source_;
    std::unique_ptr<FootprintEstimator> estimator_;
    ColormapTable colormap_;
    std::unique_ptr<PrefilteredColormapResponse> response_;
    Rgb sky_{};
};

// Parses "none|paper|smooth|exact|reference"; InputError otherwise.
FilterMode parseFilterMode(const std::string& name);

}  // namespace stochtex
