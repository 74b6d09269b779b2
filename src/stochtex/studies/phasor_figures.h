#pragma once
// Paper §6.4 (phasor noise), Figure 10: the four phasor variants as presets,
// and beside them the procedural phasor noise of Tricard et al. 2019 at the
// same frequency, bandwidth and orientation — both fields' patterns under one
// profile and their power spectra. (Figure 11, the filtering of the phasor
// sine pattern, is figure4() with figure11Options(), studies/paper.h.)
#include <array>
#include <span>
#include <vector>

#include "stochtex/core/progress.h"
#include "stochtex/noise/phasor_noise.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"

namespace stochtex {

struct Figure10Options {
    int size = 384;            // pattern side in the variants' sheet (ranges: figure10Members())
    int comparisonSize = 256;  // side of each comparison panel and spectrum
    // Both fields of the comparison: the bi-lobe of phasor-stripes takes
    // frequency, bandwidth and orientation from here (defaults: its own),
    // the procedural noise all of it (with its kernel density and seed).
    PhasorNoiseParams field{24.0, 2.5, 30.0, 8.0, 1};
};
// The entries of Figure10Options' sizes (its check; the CLI's flags).
std::span<const OptionMember<Figure10Options>> figure10Members();
// InputError (a parameter named) for unusable options: sizes, and the
// field's frequency (> 0), bandwidth (> 0), orientation, density.
void validateFigure10(const Figure10Options& options);

// The power-weighted centroid of a pattern's spectrum over the fundamental's
// lobe (the half-plane along the expected direction, |f| within half the
// expected frequency of it: the profile's harmonics and DC left out): the
// mean frequency vector, as a frequency (cycles per example period), an
// orientation (degrees, the spectra's convention) and the RMS spread around it.
struct SpectralCentroid {
    double frequency = 0, orientation = 0, spread = 0;
};

struct Figure10Result {
    // ours (tiled quadrature pair), procedural (Tricard et al.)
    std::array<SpectralCentroid, 2> centroids;
    Table table;                  // figure10.csv: the two rows
    std::vector<Figure> figures;  // figure10.png (variants), figure10_comparison.png
};
Figure10Result figure10(const Figure10Options& options, const Progress& progress = {});
// Its report: figure10.csv and the figures.
Report figure10Report(const Figure10Result& result);

}  // namespace stochtex
