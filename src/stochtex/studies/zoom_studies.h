#pragma once
// The thesis studies of the stationary zoom texture (Tavernier 2017) as
// data: sliding (section 2.2), contrast loss and its corrections (2.4,
// Figure 2.6), correlation analytic vs measured over instances (2.5,
// Figures 2.8–2.10). The frame analyses take any TextureSource; the variant
// grids build ZoomSources.
#include <array>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

// --- correlation over instances, any 1-channel source (colour: its gray) ---

struct CorrelationMeasureOptions {
    int size = 128;       // frames cover the source pixels x, y ∈ [0, size) (moved by x0, y0)
    int instances = 512;  // N
    double time = 0;
    double x0 = 0, y0 = 0;         // the window's first pixel in the source
    int pointX = -1, pointY = -1;  // the point map's reference in window pixels; −1: size/2
};
struct CorrelationMeasurement {
    // Row 0 is the source's row y = 0; the point map's reference is (size/2, size/2).
    Image measuredRadial;                     // (x, y) = Corr[I(x, 0), I(y, 0)]
    Image measuredNonRadial;                  // (x, y) = Corr[I(x, 0), I(x, y)]
    Image measuredPoint;                      // Corr with the reference point (default (size/2, size/2))
    Image analyticRadial, analyticNonRadial;  // empty when the source has no closed form
};
CorrelationMeasurement measureCorrelation(const TextureSource& source, const CorrelationMeasureOptions& options);

// --- the zoom-variant grid of Figure 2.10 ---

// The variants the thesis compares: sliding scales (eq. 2.2), the
// exponential fix (eq. 2.5) without offsets, with the quadratic "simple"
// offsets, and with hashed ("random") offsets.
enum class ZoomVariant { Sliding, Fixed, Simple, Random };
inline const EnumNames<ZoomVariant> kZoomVariantNames{{"sliding", ZoomVariant::Sliding},
                                                      {"fixed", ZoomVariant::Fixed},
                                                      {"simple", ZoomVariant::Simple},
                                                      {"random", ZoomVariant::Random}};
// params with the variant's scaling and offsets.
ZoomParams applyVariant(ZoomParams params, ZoomVariant v);

struct CorrelationStudyOptions {
    ZoomParams zoom;  // layers, scaling and offsets are set per cell
    ZoomBase base;
    std::vector<ZoomVariant> variants{ZoomVariant::Sliding, ZoomVariant::Fixed, ZoomVariant::Simple,
                                      ZoomVariant::Random};
    std::vector<int> layers{16, 8, 4, 2};
    int instances = 512;
    int size = 128;  // plots cover x, y ∈ [0, size) pixels from the zoom centre (parameter "plotSize")
};
// The entries of CorrelationStudyOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<CorrelationStudyOptions>> correlationStudyMembers();
// InputError for unusable settings, before any work.
void validateCorrelationStudy(const CorrelationStudyOptions& options);

struct CorrelationStudyResult {
    Table table;                  // one row per variant × n (correlation.csv)
    std::vector<Figure> figures;  // figure2_10.png first, then the plots of each cell
};
CorrelationStudyResult correlationStudy(const CorrelationStudyOptions& options, const StudyProgress& progress = {});
// Its report (thesis §2.5): the table (correlation.csv), Figure 2.10, each
// variant's plots at the first layer count; every plot is written.
Report correlationReport(const CorrelationStudyResult& result, const CorrelationStudyOptions& options);

// --- contrast corrections, any 1-channel source with analytic statistics ---

struct ContrastTargets {
    double mean = 0.5, variance = 1.0 / 12.0;  // μ_f, σ_f² the corrections restore
    Image reference;  // shown as an inset and as a table row (the unblended base); may be empty
};
struct ContrastStudyOptions {
    int size = 512;  // centred on the source's origin
    double time = 0;
};
std::span<const OptionMember<ContrastStudyOptions>> contrastStudyMembers();
void validateContrastStudy(const ContrastStudyOptions& options);

struct ContrastStudyResult {
    Table table;  // contrast.csv: clamped and non-monotone pixel percentages, mean, std per image
    std::vector<Figure> figures;
};
// InputError if the source is not 1-channel or has no analytic statistics.
ContrastStudyResult contrastStudy(const TextureSource& source, const ContrastTargets& targets,
                                  const ContrastStudyOptions& options);
// The zoom texture's targets: its first lattice's μ_f, σ_f² and values.
ContrastTargets zoomContrastTargets(const ZoomSource& source, int size);
// The contrast study of the zoom texture (params, base) at its time params.time.
ContrastStudyResult zoomContrastStudy(const ZoomParams& params, const ZoomBase& base,
                                      const ContrastStudyOptions& options);
// Its report (thesis §2.4): contrast.csv and the figures; n: the zoom's layers.
Report contrastReport(const ContrastStudyResult& result, int layers);

// --- sliding: the same frame pair with eq. 2.2 and eq. 2.5, and a_0(t) ---

std::vector<Figure> slidingStudy(const ZoomParams& params, const ZoomBase& base);
Report slidingReport(const std::vector<Figure>& figures);  // thesis §2.2

}  // namespace stochtex
