#pragma once
// How a program is filtered (FilteredGraph, the GPU host, the export):
// where a pixel's footprint statistics come from and the response that
// turns them into a colour. The named filters of the CLI and the papers are
// shorthands for pairs:
//   none      — point: S = H∘N at the pixel centre (aliases when zoomed out);
//   paper     — estimators + the section-5 prefiltered table;
//   smooth    — estimators + the smooth prefiltered table;
//   exact     — brute-force footprint statistics + the smooth table: isolates
//               the error of the Gaussian approximation (eq. 5) from the
//               error of the estimators (paper Fig. 4b);
//   reference — S̄: the average of the program's point colour over the
//               footprint parallelogram by an n×n stratified grid,
//               n = clamp(⌈2·extent in texels⌉, 8, referenceMaxSamples).
// The response is the program's last op: a colormap's prefiltered table, or
// under the lean response a plain file's normal map compiles to a lean op
// (GraphPattern::build picks the program).
#include <array>
#include <string>
#include <utility>

#include "stochtex/core/enum_names.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

// Where a pixel's footprint statistics come from.
enum class StatisticsSource {
    Point,       // N at the pixel centre (no filtering: S = H∘N, aliases when zoomed out)
    Estimators,  // μ̂, Σ̂ from the MIP pyramids (paper §4)
    Exact,       // brute-force statistics of the footprint (isolates the Gaussian approximation, Fig. 4b)
    Reference,   // S̄: the point colour averaged over the footprint by supersampling (eq. 3)
};
inline const EnumNames<StatisticsSource> kStatisticsSourceNames{{"point", StatisticsSource::Point},
                                                                {"estimators", StatisticsSource::Estimators},
                                                                {"exact", StatisticsSource::Exact},
                                                                {"reference", StatisticsSource::Reference}};

// What a plain pattern file's program ends in.
enum class ResponseKind {
    PrefilteredColormap,  // H̄(μ, σ_x, σ_y), paper eq. 5–6 (§5): the colormap op
    Lean,                 // LEAN-mapped shading of the file's normal map (§6.5): the lean op
    // A PBR material's maps of the file's normal map (the surface op), as
    // data (no transfer function): its tangent-space normal, its roughness,
    // its height.
    Normal,
    Roughness,
    Height,
};
inline const EnumNames<ResponseKind> kResponseKindNames{{"prefiltered-colormap", ResponseKind::PrefilteredColormap},
                                                        {"lean", ResponseKind::Lean},
                                                        {"normal", ResponseKind::Normal},
                                                        {"roughness", ResponseKind::Roughness},
                                                        {"height", ResponseKind::Height}};
// Whether the response reads the file's normal map (else its colours).
inline bool readsNormalMap(ResponseKind kind) { return kind != ResponseKind::PrefilteredColormap; }
// The surface op's map (SurfaceParams::map: 0 normal, 1 roughness, 2
// height) a PBR response ends in; −1: not a PBR map.
inline int surfaceMap(ResponseKind kind) {
    return kind == ResponseKind::Normal      ? 0
           : kind == ResponseKind::Roughness ? 1
           : kind == ResponseKind::Height    ? 2
                                             : -1;
}
// Whether its values are data, written without a transfer function (the
// PBR maps), rather than colours.
inline bool writesData(ResponseKind kind) { return surfaceMap(kind) >= 0; }
// A PBR material's set (bake-image --pbr): each image's response and name.
inline const std::pair<ResponseKind, const char*> kPbrMaps[] = {{ResponseKind::PrefilteredColormap, "albedo"},
                                                                {ResponseKind::Normal, "normal"},
                                                                {ResponseKind::Roughness, "roughness"},
                                                                {ResponseKind::Height, "height"}};

// A response and its parameters, as a value (FilterOptions holds one).
struct ResponseOptions {
    ResponseKind kind = ResponseKind::PrefilteredColormap;
    PrefilterMode prefilter = PrefilterMode::Smooth;  // the prefiltered tables' σ levels
    bool covariance = true;  // Lean: read ĉov of the slopes (false: the "without covariance" variant, ĉov := 0)
    bool operator==(const ResponseOptions&) const = default;
};

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

struct ParamInfo;

// The anisotropic probes a user's render starts with (the CLI's --aniso,
// the workbench): 8. An isotropic footprint (the zoom view) takes one probe
// whatever K is, so only oblique views pay, and they need it (with K = 1,
// `render --view plane --filter smooth` blurs the distance, as a texture
// without anisotropic filtering does); 8 is also what engines commonly set.
// FilterOptions keeps 1, the paper's isotropic estimators, for the studies.
constexpr int kDefaultAniso = 8;

struct FilterOptions {
    StatisticsSource source = StatisticsSource::Estimators;
    ResponseOptions response;  // the smooth prefiltered colormap
    int aniso = 1;             // K, 1..16
    VarianceEstimator estimator = VarianceEstimator::Paper;
    // The brute-force sources (exact, reference) sample n×n per pixel,
    // n = clamp(⌈2·extent in texels⌉, referenceMinSamples, referenceMaxSamples);
    // min = max fixes n (studies/reference_samples.h chooses it by convergence).
    int referenceMaxSamples = 64;           // per axis
    int referenceMinSamples = 8;            // per axis
    bool pack8 = false;                     // 8-bit pyramids (paper §5)
    CpuKernel cpuKernel = CpuKernel::Simd;  // the CPU evaluator's lanes or its scalar reference

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
// "exact/prefiltered-colormap") so that it is never mistaken for a name
// (the bake manifest's "filter" and what the flags take).
std::string filterName(const FilterOptions& options);
// filterName, and the estimator where the statistics come from one other than
// the default: "smooth/sub-probes" (what a command prints, a study's row).
std::string filterLabel(const FilterOptions& options);
// The anisotropic probes K and the reference's samples per axis, each
// described once: the range validateFilterOptions checks, the flag and help
// the CLI sets it by.
const ParamInfo& anisoParam();
const ParamInfo& referenceMaxSamplesParam();
// InputError naming `aniso` or `referenceMaxSamples` when out of range.
void validateFilterOptions(const FilterOptions& options);

// S̄ (paper eq. 3): the average of pointColour over the footprint
// parallelogram uv + J·(s, t), s, t ∈ [−½, ½], on an n×n grid of cell
// centres.
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

}  // namespace stochtex
