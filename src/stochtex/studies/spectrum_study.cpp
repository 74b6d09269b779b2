#include "stochtex/studies/spectrum_study.h"

#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"

namespace stochtex {

std::span<const OptionMember<SpectrumStudyOptions>> spectrumStudyMembers() {
    using O = SpectrumStudyOptions;
    static const OptionMember<O> members[] = {
        {"instances", "Instances averaged (patterns: moved windows; zoom: white-noise lattices)", 1, 100000,
         &O::instances},
        {"radialBins", "Bins of the radial profile", 1, 4096, &O::radialBins},
        {"angularBins", "Bins of the angular profile", 1, 3600, &O::angularBins},
        {"rMin", "Inner radius of the angular profile's annulus, cycles/pixel", 0, 0.75, &O::rMin},
        {"rMax", "Outer radius of the angular profile's annulus, cycles/pixel", 0, 0.75, &O::rMax},
    };
    return members;
}

void validateSpectrumStudy(const SpectrumStudyOptions& o, const TextureSource* source) {
    const SourceRegion& r = o.region;
    if (r.width < 4 || r.height < 4 || r.width > 4096 || r.height > 4096)
        throw InputError::parameter(
            "size", "must be 4…4096 pixels a side, got " + std::to_string(r.width) + "×" + std::to_string(r.height));
    if (o.times.empty()) throw InputError::parameter("times", "needs at least one time");
    for (double t : o.times)
        if (!std::isfinite(t)) throw InputError::parameter("times", "must be finite");
    checkMembers(o, spectrumStudyMembers());
    if (double(o.instances) * double(o.times.size()) > 100000)
        throw InputError::parameter("instances", "must leave at most 100000 frames in all, got " +
                                                     std::to_string(o.instances) + " × " +
                                                     std::to_string(o.times.size()) + " times");
    if (!(o.rMin < o.rMax)) throw InputError::parameter("rMin", "the annulus needs rMin < rMax");
    if (source) {
        for (double t : o.times) source->checkWindow(o.region, t);
        source->checkInstances(o.instances);
    }
}

namespace {

std::string geometryText(const SpectrumGeometry& g) {
    char s[256];
    std::snprintf(s, sizeof s, "peak at %.4f cycles/pixel, %.1f°; anisotropy λ₁/λ₂ = %.2f along %.1f°", g.peakRadius,
                  g.peakOrientationDeg, g.anisotropy, g.orientationDeg);
    return s;
}

}  // namespace

SpectrumStudyResult spectrumStudy(const TextureSource& source, const SpectrumStudyOptions& o,
                                  const StudyProgress& progress) {
    validateSpectrumStudy(o, &source);
    SpectrumStudyResult r;
    SpectrumAccumulator acc(o.region.width, o.region.height, o.window);
    const int total = int(o.times.size()) * o.instances;
    Image first;
    int done = 0;
    for (double t : o.times)
        for (int i = 0; i < o.instances; ++i) {
            if (progress)
                progress(double(done) / total, "frame " + std::to_string(done + 1) + "/" + std::to_string(total));
            Image frame = source.render(o.region, t, i);
            acc.add(frame);
            if (done++ == 0) first = std::move(frame);
        }
    if (progress) progress(1.0, "profiles");
    r.spectrum = acc.mean();
    r.radial = radialProfile(r.spectrum, o.radialBins);
    r.angular = angularProfile(r.spectrum, o.angularBins, o.rMin, o.rMax);
    r.geometry = spectrumGeometry(r.spectrum, o.rMin, o.rMax);

    r.summary.columns = {{"frames", "frames", ""},
                         {"peak_radius", "peak |f|", "cycles/pixel"},
                         {"peak_orientation", "peak θ", "°"},
                         {"anisotropy", "anisotropy λ₁/λ₂", ""},
                         {"orientation", "major axis", "°"},
                         {"mean_radius", "mean |f|", "cycles/pixel"},
                         {"angular_max_min", "angular max/min", ""}};
    const SpectrumGeometry& g = r.geometry;
    r.summary.add({TableCell::integer(acc.count()), TableCell::value(g.peakRadius),
                   TableCell::value(g.peakOrientationDeg, "%.1f"), TableCell::value(g.anisotropy, "%.3f"),
                   TableCell::value(g.orientationDeg, "%.1f"), TableCell::value(g.meanRadius),
                   TableCell::value(g.angularMaxMin, "%.3f")});
    r.profile.columns = {{"radius", "|f|", "cycles/pixel"}, {"power", "P", ""}};
    for (size_t b = 0; b < r.radial.radius.size(); ++b)
        r.profile.add({TableCell::value(r.radial.radius[b]), TableCell::value(r.radial.power[b], "%.6g")});

    const std::string frames = std::to_string(acc.count()) + (acc.count() == 1 ? " frame" : " frames");
    r.figures.push_back({"spectrum.png", logSpectrumImage(r.spectrum),
                         "Power spectrum, log scale over 4 decades, zero frequency at the centre (" + frames + ", " +
                             enumName(kSpectrumWindowNames, o.window) + " window): " + geometryText(g) + "."});
    PlotSeries radial{"P(|f|)", r.radial.radius, r.radial.power, {0.1f, 0.3f, 0.8f}};
    LinePlotOptions ro;
    ro.title = "Radial profile";
    ro.xLabel = "|f| (cycles/pixel)";
    ro.yLabel = "mean power";
    ro.logY = true;
    r.figures.push_back(chartFigure("radial.png", {{radial}, ro}, "Mean power per ring of frequencies."));
    PlotSeries angular{"P(θ)", r.angular.angleDeg, r.angular.power, {0.8f, 0.2f, 0.1f}};
    LinePlotOptions ao;
    ao.title = "Angular profile";
    ao.xLabel = "θ (°, counter-clockwise from +x)";
    ao.yLabel = "mean power";
    ao.xMin = 0;
    ao.xMax = 180;
    char annulus[96];
    std::snprintf(annulus, sizeof annulus, "%.3f ≤ |f| ≤ %.3f", o.rMin, o.rMax);
    r.figures.push_back(chartFigure(
        "angular.png", {{angular}, ao},
        std::string("Mean power per orientation over ") + annulus +
            ": flat for an isotropic texture; max/min = " + TableCell::value(g.angularMaxMin, "%.2f").text + "."));
    r.figures.push_back({"frame.png", encodeTransfer(first, o.frameTransfer), "The first frame analysed."});
    return r;
}

Report spectrumReport(const SpectrumStudyResult& r, const std::string& sourceName) {
    return sectionReport("Power spectrum: " + sourceName,
                         {{"spectrum.csv", r.summary}, {"radial.csv", r.profile, false}}, r.figures);
}

}  // namespace stochtex
