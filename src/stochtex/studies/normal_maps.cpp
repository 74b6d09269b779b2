#include "stochtex/studies/normal_maps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/cpu_renderer.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/paper.h"

namespace stochtex {

const std::array<LeanVariantInfo, 8> kLeanVariants{{
    {LeanVariant::Reference, "reference", "reference (supersampled)",
     [](FilterOptions& o) { o.source = StatisticsSource::Reference; }},
    {LeanVariant::Ours, "ours", "ours (eq. 9, 14, 18)", [](FilterOptions&) {}},
    {LeanVariant::NoCovariance, "no-covariance", "ours without covariance",
     [](FilterOptions& o) { o.response.covariance = false; }},
    {LeanVariant::DeliotHeitz, "deliot-heitz", "Deliot–Heitz (constant variance per LOD)",
     [](FilterOptions& o) {
         o.estimator = VarianceEstimator::DeliotHeitz;
         o.response.covariance = false;
     }},
    {LeanVariant::SubProbes, "sub-probes", "ours, sub-probes estimator",
     [](FilterOptions& o) { o.estimator = VarianceEstimator::SubProbes; }},
    {LeanVariant::SubProbes4x4, "sub-probes-4x4", "ours, sub-probes-4x4 estimator",
     [](FilterOptions& o) { o.estimator = VarianceEstimator::SubProbes4x4; }},
    {LeanVariant::SubProbes8x8FineMeans, "sub-probes-8x8-fine-means", "ours, sub-probes-8x8-fine-means estimator",
     [](FilterOptions& o) { o.estimator = VarianceEstimator::SubProbes8x8FineMeans; }},
    {LeanVariant::Exact, "exact-statistics", "exact footprint statistics",
     [](FilterOptions& o) { o.source = StatisticsSource::Exact; }},
}};

FilterOptions leanVariantOptions(const LeanVariantInfo& variant, int aniso, int referenceSamples) {
    FilterOptions o;
    o.response.kind = ResponseKind::Lean;
    o.aniso = aniso;
    o.referenceMaxSamples = referenceSamples;
    variant.apply(o);
    return o;
}

std::span<const OptionMember<Figure12Options>> figure12Members() {
    using O = Figure12Options;
    static const OptionMember<O> members[] = {
        {"referenceSamples", "Max reference samples per axis", 1, 4096, &O::referenceSamples},
    };
    return members;
}

void validateFigure12(const Figure12Options& o) {
    if (o.width < 32 || o.height < 32 || o.width > 4096 || o.height > 4096)
        throw InputError::parameter(
            "size", "must be in [32, 4096] per side, got " + std::to_string(o.width) + "x" + std::to_string(o.height));
    checkMembers(o, figure12Members());
    const auto& c = o.crop;
    if (!(c[0] >= 0 && c[0] < c[2] && c[2] <= 1 && c[1] >= 0 && c[1] < c[3] && c[3] <= 1))
        throw InputError::parameter(
            "crop", "must be fractions 0 <= x0 < x1 <= 1, 0 <= y0 < y1 <= 1 of the view, got [" + formatValue(c[0]) +
                        ", " + formatValue(c[1]) + ", " + formatValue(c[2]) + ", " + formatValue(c[3]) + "]");
    if (!o.pattern.normalMap) throw InputError(o.name + ": figure 12 needs a pattern with a normal_map");
}

namespace {

struct Rect {
    int x0, y0, x1, y1;
};

Image cropped(const Image& img, const Rect& r) { return crop(img, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0); }

double meanOf(const Image& img) {
    double s = 0;
    for (const float v : img.data()) s += v;
    return s / double(img.data().size());
}

}  // namespace

Figure12Result figure12(const Figure12Options& o, const Progress& progress) {
    validateFigure12(o);
    Camera cam;
    cam.kind = Camera::Kind::Plane;
    cam.view = View{o.width, o.height, o.scale};
    cam.tiltDeg = o.tiltDeg;
    cam.fovDeg = o.fovDeg;
    validateCamera(cam);
    const Rect crop{int(o.crop[0] * o.width), int(o.crop[1] * o.height), std::max(int(o.crop[2] * o.width), 1),
                    std::max(int(o.crop[3] * o.height), 1)};

    constexpr int n = int(kLeanVariants.size());
    Image views[n], errors[n];
    for (int k = 0; k < n; ++k) {
        // The supersampled reference and the exact statistics take nearly all the time.
        const double from = k == 0 ? 0.0 : 0.5 + 0.5 * (k - 1) / (n - 1), to = k == 0 ? 0.5 : from + 0.5 / (n - 1);
        const LeanVariantInfo& variant = kLeanVariants[size_t(k)];
        const FilterOptions fo = leanVariantOptions(variant, o.aniso, o.referenceSamples);
        // The file's lean program (GraphPattern::build), as `render` draws it.
        views[k] = makeCpuRenderer(o.pattern, fo)->render(cam, progressPart(progress, from, to, variant.name));
    }
    Figure12Result res;
    res.table.columns = {{"variant", "variant", ""},
                         {"mean_error_global", "mean ‖Ŝ − S̄‖₂, global view", ""},
                         {"mean_error_crop", "mean ‖Ŝ − S̄‖₂, mid-distance crop", ""}};
    std::vector<float> all;
    for (int k = 1; k < n; ++k) {
        Figure12Row row;
        row.variant = kLeanVariants[size_t(k)].variant;
        errors[k] = errorMap(views[k], views[0], row.meanErrorGlobal);
        row.meanErrorCrop = meanOf(cropped(errors[k], crop));
        all.insert(all.end(), errors[k].data().begin(), errors[k].data().end());
        res.rows.push_back(row);
        res.table.add({TableCell(kLeanVariants[size_t(k)].name), TableCell::value(row.meanErrorGlobal),
                       TableCell::value(row.meanErrorCrop)});
    }
    // One colour scale for every error map: the 99.5th percentile of all.
    std::nth_element(all.begin(), all.begin() + ptrdiff_t(all.size() * 995 / 1000), all.end());
    const double vmax = std::max(1e-3, double(all[all.size() * 995 / 1000]));

    const int thumbW = std::min(o.width, 360), thumbH = std::max(1, thumbW * o.height / o.width);
    // The crop magnified by a whole factor, at least 2, so that its pixels
    // (where the variants differ) are seen as pixels: at the thumbnails'
    // width or more (an unmagnified crop made two estimators with errors 2×
    // apart look the same).
    const int cropPixelsW = std::max(1, crop.x1 - crop.x0), cropPixelsH = std::max(1, crop.y1 - crop.y0);
    const int magnify = std::max(2, int(std::lround(double(thumbW) / cropPixelsW)));
    const int cropW = cropPixelsW * magnify, cropH = cropPixelsH * magnify;
    std::vector<std::vector<Image>> rows(4);
    std::vector<std::vector<std::string>> texts(4);
    std::vector<Figure> images;
    for (int k = 0; k < n; ++k) {
        const std::string tag = kLeanVariants[size_t(k)].name, caption = kLeanVariants[size_t(k)].caption;
        // Figures hold display codes (report/page.h): renders are encoded, error maps drawn so.
        const Image shown = srgbFromLinear(views[k]);
        Image cropShown = resizeNearest(cropped(shown, crop), cropW, cropH);
        rows[0].push_back(resizeSmooth(shown, thumbW, thumbH));
        rows[1].push_back(cropShown);
        // Errors to 4 decimals (the CSV keeps every digit).
        const auto fixed4 = [](double v) {
            char text[32];
            std::snprintf(text, sizeof text, "%.4f", v);
            return std::string(text);
        };
        const std::string err = k == 0 ? ""
                                       : ", error " + fixed4(res.rows[size_t(k - 1)].meanErrorGlobal) + " / " +
                                             fixed4(res.rows[size_t(k - 1)].meanErrorCrop) + " (crop)";
        texts[0].push_back(caption + err);
        texts[1].push_back(caption + ", mid-distance crop, ×" + std::to_string(magnify));
        images.push_back({"figure12_" + tag + ".png", shown, ""});
        images.push_back({"figure12_" + tag + "_crop.png", std::move(cropShown), ""});
        if (k == 0) continue;
        Image e = colourise(errors[k], 0.0, vmax, HeatPalette::Viridis);
        rows[2].push_back(resizeSmooth(e, thumbW, thumbH));
        rows[3].push_back(resizeNearest(cropped(e, crop), cropW, cropH));
        texts[2].push_back("error, " + caption);
        texts[3].push_back("error (crop), " + caption);
        images.push_back({"figure12_" + tag + "_error.png", std::move(e), ""});
    }
    rows.push_back(
        {colourLegend(0.0, vmax, HeatPalette::Viridis, "error ‖Ŝ − S̄‖₂ (RGB, linear), one scale for every map")});
    texts.push_back({""});
    res.figures.push_back({"figure12.png", sheet(rows, texts),
                           "Figure 12 (" + o.name + ", " + std::to_string(o.width) + "×" + std::to_string(o.height) +
                               ", tilt " + formatValue(o.tiltDeg) +
                               "°): LEAN-mapped procedural normal map; rows = the "
                               "global view, the mid-distance crop, their errors against the reference (≤ " +
                               std::to_string(o.referenceSamples) + "² samples per pixel)."});
    for (auto& f : images) res.figures.push_back(std::move(f));
    return res;
}

Report figure12Report(const Figure12Result& r) {
    return sectionReport("Figure 12: LEAN-mapped procedural normal map", {{"figure12.csv", r.table}}, r.figures);
}

}  // namespace stochtex
