#pragma once
// The response stage: what turns the statistics of the noise vector field N
// over a pixel footprint into an output colour. Filtering has two
// independent axes — where the statistics come from (StatisticsSource: the
// pixel centre, the estimators of paper §4, exact footprint statistics, or
// the supersampled reference which averages the point response) and which
// response reads them (the prefiltered colormap; the lean response is the
// program's lean op, below). A response says whether it needs the covariance
// of (N_x, N_y): when it does not, the covariance pyramid is neither built
// nor fetched, on the CPU or the GPU.
//
// The lean response is not one of these classes: a pattern file's normal map
// under it compiles to the program "slopes, albedo → lean op"
// (GraphPattern::build), as any response that shades more than a colormap
// would: an op (pattern/ops/ops.h).
#include <array>
#include <memory>

#include "stochtex/core/enum_names.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/pattern_file.h"
#include "stochtex/pattern/prefiltered_colormap.h"

namespace stochtex {

// Where a pixel's footprint statistics come from.
enum class StatisticsSource {
    Point,       // N at the pixel centre (no filtering: S = H∘N, aliases when zoomed out)
    Estimators,  // μ̂, Σ̂ from the MIP pyramids (paper §4)
    Exact,       // brute-force statistics of the footprint (isolates the Gaussian approximation, Fig. 4b)
    Reference,   // S̄: the point response averaged over the footprint by supersampling (eq. 3)
};
inline const EnumNames<StatisticsSource> kStatisticsSourceNames{{"point", StatisticsSource::Point},
                                                                {"estimators", StatisticsSource::Estimators},
                                                                {"exact", StatisticsSource::Exact},
                                                                {"reference", StatisticsSource::Reference}};

// What turns statistics into a colour.
enum class ResponseKind {
    PrefilteredColormap,  // H̄(μ, σ_x, σ_y), paper eq. 5–6 (§5)
    Lean,                 // LEAN-mapped shading of the pattern's slope field (§6.5, kernel/lean.glsl)
};
inline const EnumNames<ResponseKind> kResponseKindNames{{"prefiltered-colormap", ResponseKind::PrefilteredColormap},
                                                        {"lean", ResponseKind::Lean}};

// A response and its parameters, as a value (FilterOptions holds one).
struct ResponseOptions {
    ResponseKind kind = ResponseKind::PrefilteredColormap;
    PrefilterMode prefilter = PrefilterMode::Smooth;  // PrefilteredColormap: the table's σ levels
    bool covariance = true;  // Lean: read ĉov of the slopes (false: the "without covariance" variant, ĉov := 0)
    bool operator==(const ResponseOptions&) const = default;
};

class Response {
public:
    virtual ~Response() = default;
    // The colour of a footprint whose N has these statistics (blending space).
    virtual Rgb filtered(const FootprintStats& s) const = 0;
    // Whether filtered() reads s.cov: the estimators then need the
    // covariance pyramid of a shared-offset pair.
    virtual bool needsCovariance() const = 0;
};

// The prefiltered colormap H̄(μ, σ_x, σ_y) of paper eq. 5–6 (§5): a Gaussian
// of axis-aligned covariance, so the covariance is not needed.
class PrefilteredColormapResponse final : public Response {
public:
    PrefilteredColormapResponse(const ColormapTable& h, PrefilterMode mode) : table_(h, mode) {}
    Rgb filtered(const FootprintStats& s) const override {
        return table_.sample(s.mean[0], s.mean[1], s.sigmaX(), s.sigmaY());
    }
    bool needsCovariance() const override { return false; }
    const PrefilteredColormap& table() const { return table_; }

private:
    PrefilteredColormap table_;
};

// The response that `options` names over the colormap h (blending space).
// The lean response is a file's program's last op (GraphPattern::build):
// InputError naming `response` for it here.
std::unique_ptr<Response> makeResponse(const ResponseOptions& options, const ColormapTable& h);

}  // namespace stochtex
