#include "stochtex/studies/phasor_figures.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/noise/spectrum.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/report/plot.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

namespace {

constexpr double kPi = std::numbers::pi;

// The gray level of a render (the mean of its channels), times a separable
// Hann window: neither field is periodic over the window in general (the
// procedural one never is), and the window keeps the borders' jumps out of
// the spectrum. Both fields go through the same window.
// The mean is removed first: the window would turn it into a low-frequency bump.
Image windowedGray(const Image& rgb) {
    const Image g = toGray(rgb);
    const double mean = channelStats(g).mean;
    Image out(g.width(), g.height(), 1);
    const auto hann = [](int i, int n) { return 0.5 - 0.5 * std::cos(2.0 * kPi * (i + 0.5) / n); };
    for (int y = 0; y < g.height(); ++y)
        for (int x = 0; x < g.width(); ++x)
            out.at(x, y) = float((g.at(x, y) - mean) * hann(x, g.width()) * hann(y, g.height()));
    return out;
}

SpectralCentroid centroid(const Image& power, double expectedFrequency, double expectedDegrees) {
    const int n = power.width();
    const double t = expectedDegrees * kPi / 180.0;
    const double du = std::cos(t), dv = -std::sin(t);  // the wave direction in (u, v), v down the rows
    // One lobe of the fundamental: the half-plane along d, |f| within f₀/2 of
    // f₀ (a profile's harmonics sit at 2f₀, 3f₀, …; DC is out).
    const auto inBand = [&](double fu, double fv) {
        const double r = std::hypot(fu, fv);
        return fu * du + fv * dv > 0.0 && std::abs(r - expectedFrequency) < 0.5 * expectedFrequency;
    };
    double w = 0, su = 0, sv = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double fu = fftFrequency(x, n), fv = fftFrequency(y, n);
            if (!inBand(fu, fv)) continue;
            w += power.at(x, y);
            su += power.at(x, y) * fu;
            sv += power.at(x, y) * fv;
        }
    SpectralCentroid c;
    if (w <= 0) return c;
    su /= w;
    sv /= w;
    double spread = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double fu = fftFrequency(x, n), fv = fftFrequency(y, n);
            if (!inBand(fu, fv)) continue;
            spread += power.at(x, y) * ((fu - su) * (fu - su) + (fv - sv) * (fv - sv));
        }
    c.frequency = std::hypot(su, sv);
    c.orientation = std::atan2(-sv, su) * 180.0 / kPi;
    c.spread = std::sqrt(spread / w);
    return c;
}

}  // namespace

std::span<const OptionMember<Figure10Options>> figure10Members() {
    using O = Figure10Options;
    static const OptionMember<O> members[] = {
        {"size", "Pattern size in the variants' sheet", 64, 2048, &O::size},
        {"comparisonSize", "Side of each comparison panel (one example period)", 32, 2048, &O::comparisonSize},
    };
    return members;
}

void validateFigure10(const Figure10Options& o) {
    checkMembers(o, figure10Members());
    validatePhasorNoise(o.field);
}

Figure10Result figure10(const Figure10Options& o, const Progress& progress) {
    validateFigure10(o);
    Figure10Result res;
    res.figures.push_back(
        paperFigureSheet(10, o.size, progressPart(progress, 0.0, 0.5, "figure10: the four variants")));

    // Ours: phasor-stripes with the field's bi-lobe; the window is one example
    // period (the frequencies are cycles per period on both sides).
    const Progress part = progressPart(progress, 0.5, 1.0, "figure10: procedural phasor noise");
    PatternSpec spec = loadPreset("phasor-stripes");
    for (NoiseSpec& n : spec.noise) {
        SpectrumComponent& c = n.spectrum.components.front();
        c.frequency = o.field.frequency;
        c.bandwidth = o.field.bandwidth;
        c.orientation = o.field.orientation;
        validateSpectrumWork(n.spectrum);
    }
    const GraphPattern program = GraphPattern::build(spec);
    FilterOptions unfiltered;
    unfiltered.source = StatisticsSource::Point;
    const FilteredGraph renderer(program, unfiltered);
    Camera zoom;
    zoom.view.scale = double(program.exampleSize()) / double(o.comparisonSize);
    const SourceRegion region{o.comparisonSize, o.comparisonSize, 0, 0};
    const CameraSource ours(renderer, zoom);
    const PhasorNoiseSource procedural(o.field, program.tables().front().point, zoom.view, program.exampleSize());
    const std::array<Image, 2> renders{ours.render(region, 0.0, 0), procedural.render(region, 0.0, 0)};
    if (part) part(0.8, "spectra");

    const char* names[2] = {"ours (tiled quadrature pair)", "procedural (Tricard et al. 2019)"};
    res.table.columns = {{"field", "field", ""},
                         {"frequency", "spectral centroid frequency", "cycles/period"},
                         {"orientation", "centroid orientation", "degrees"},
                         {"spread", "RMS spread around it", "cycles/period"}};
    std::vector<std::vector<Image>> rows(2);
    std::vector<std::vector<std::string>> captions(2);
    for (size_t i = 0; i < 2; ++i) {
        const Image power = powerSpectrum(windowedGray(renders[i]));
        res.centroids[i] = centroid(power, o.field.frequency, o.field.orientation);
        const SpectralCentroid& c = res.centroids[i];
        res.table.add(
            {names[i], TableCell::value(c.frequency), TableCell::value(c.orientation), TableCell::value(c.spread)});
        rows[0].push_back(srgbFromLinear(renders[i]));
        captions[0].push_back(names[i]);
        rows[1].push_back(colourise(displaySpectrum(power), 0.0, 1.0, HeatPalette::Viridis));
        char b[160];
        std::snprintf(b, sizeof b, "power spectrum (log): centroid %.1f cycles, %.1f°, spread %.1f", c.frequency,
                      c.orientation, c.spread);
        captions[1].push_back(b);
    }
    char title[640];
    std::snprintf(title, sizeof title,
                  "Figure 10, comparison: the paper's phasor field (a bi-lobe noise and its quadrature partner, tiled "
                  "and blended) and procedural phasor noise (sparse complex Gabor kernels, %.3g per cell), both at "
                  "%.3g cycles per period, bandwidth %.3g, %.3g°, under the sine profile; one example period per "
                  "panel (%d²), spectra of the Hann-windowed gray levels, zero frequency at the centre.",
                  o.field.density, o.field.frequency, o.field.bandwidth, o.field.orientation, o.comparisonSize);
    res.figures.push_back({"figure10_comparison.png", sheet(rows, captions), title});
    if (part) part(1.0, "");
    return res;
}

Report figure10Report(const Figure10Result& r) {
    return sectionReport("Figure 10: phasor noise, and procedural phasor noise beside it", {{"figure10.csv", r.table}},
                         r.figures);
}

}  // namespace stochtex
