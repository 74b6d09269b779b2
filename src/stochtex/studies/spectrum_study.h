#pragma once
// The power spectrum of any texture source (thesis §2.7, Figure 2.22):
// frames of a window at some times and instances, their mean periodogram
// (analysis/power_spectrum.h), its radial and angular profiles and the
// figures of its shape, as a table and figures for a report.
#include <span>
#include <vector>

#include "stochtex/analysis/power_spectrum.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

struct SpectrumStudyOptions {
    SourceRegion region = SourceRegion::centred(256, 256);  // 4…4096 pixels a side
    std::vector<double> times{0.0};                         // every time is averaged…
    int instances = 1;  // …with instances 0…N−1 at each (at most 100000 frames in all)
    SpectrumWindow window = SpectrumWindow::Hann;
    int radialBins = 64;
    int angularBins = 36;
    double rMin = 0.02, rMax = 0.5;  // the annulus of the angular profile and the shape figures, cycles/pixel
    // How the frames' values are shown in frame.png: Linear as they are (data,
    // image files' codes), Srgb encoded (linear-light colour renders).
    Transfer frameTransfer = Transfer::Linear;
};
// The entries of SpectrumStudyOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<SpectrumStudyOptions>> spectrumStudyMembers();
// InputError naming the parameter, before any work; with a source, also its
// checkWindow at every time.
void validateSpectrumStudy(const SpectrumStudyOptions& options, const TextureSource* source = nullptr);

struct SpectrumStudyResult {
    Image spectrum;  // the mean periodogram, centred
    RadialProfile radial;
    AngularProfile angular;
    SpectrumGeometry geometry;
    Table summary;                // spectrum.csv: one row of the shape figures
    Table profile;                // radial.csv: radius, power
    std::vector<Figure> figures;  // spectrum.png, radial.png, angular.png, frame.png
};
SpectrumStudyResult spectrumStudy(const TextureSource& source, const SpectrumStudyOptions& options,
                                  const StudyProgress& progress = {});
// Its report: the summary (spectrum.csv), the radial profile (radial.csv,
// not on the page) and the figures, titled by the source's name.
Report spectrumReport(const SpectrumStudyResult& result, const std::string& sourceName);

}  // namespace stochtex
