#pragma once
// The response stage: what turns the statistics of the noise vector field N
// over a pixel footprint into an output colour. Filtering has two
// independent axes — where the statistics come from (StatisticsSource: the
// pixel centre, the estimators of paper §4, exact footprint statistics, or
// the supersampled reference which averages the point response) and which
// response reads them (the prefiltered colormap today; LEAN lobes and
// phasor profiles next). A response says whether it needs the covariance
// of (N_x, N_y): when it does not, the covariance pyramid is neither built
// nor fetched, on the CPU or the GPU.
//
// A new response kind: a ResponseKind value and its name, a Response class
// and its case in makeResponse (here), and its GLSL chunk (gpu/programs.cpp,
// responseChunk), which defines
// `vec3 footprintResponse(vec2 mean, vec2 var, float cov)`.
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

// LEAN mapping (Olano & Baker 2010, paper §6.5): the statistics are those
// of the slope pair (N_x, N_y) = (∂z/∂x, ∂z/∂y); their mean and 2×2
// covariance plus the base roughness make an anisotropic Beckmann lobe
// (kernel/lean.glsl), lit by a directional light. The slopes of one height
// field are correlated, so the covariance is read (unless the variant
// without it is asked for).
class LeanResponse final : public Response {
public:
    using Direction = std::array<float, 3>;
    static constexpr Direction kFromAbove{0.0f, 0.0f, 1.0f};
    LeanResponse(const LeanShading& shading, bool covariance);
    // Seen from `camera` (the unit direction towards the eye, used when the
    // shading fixes no view direction of its own).
    Rgb filtered(const FootprintStats& s, const Direction& camera) const;
    Rgb filtered(const FootprintStats& s) const override { return filtered(s, kFromAbove); }
    bool needsCovariance() const override { return covariance_; }
    // The unfiltered shading of one slope: the base lobe around it.
    Rgb point(float slopeX, float slopeY, const Direction& camera = kFromAbove) const;

private:
    LeanShading shading_;
    bool covariance_;
};

// The response that `options` names, over the colormap h (blending space)
// or, for Lean, the shading of the pattern's normal map (InputError naming
// `response` without one): the one place a response kind is built.
std::unique_ptr<Response> makeResponse(const ResponseOptions& options, const ColormapTable& h,
                                       const LeanShading* shading = nullptr);

}  // namespace stochtex
