#pragma once
// Perception stimuli (thesis §2.6.2, Figures 2.13–2.14): partly correlated
// tiled white noise (noise/tiled_white_noise.h, eq. 2.24 and 2.28) shown as
// display images, a set of them over a grid of tile sizes w and tile-to-tile
// correlations in a seeded random order, and the yes/no experiment that shows
// them ("did you see a repeating pattern?") as one self-contained HTML page.
// The experiment's answers are analysed by stimuli_analysis.h.
//
// Values are display values: the PNG codes / 255 that the screen shows as
// they are (no transfer function is applied on writing), so "mean" is the
// mean grey code of the stimulus and of the screen between stimuli, and the
// luminance the viewer sees depends on the monitor's calibration.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "stochtex/image/image.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"

namespace stochtex {

struct StimulusOptions {
    int size = 256;            // image side, pixels
    int tile = 32;             // w: the repeated block is w×w pixels; divides size
    double correlation = 0.5;  // between pixels one tile apart, [0, 1] (eq. 2.28; α from it)
    uint32_t seed = 0;
    double mean = 0.5;      // mean display value, (0, 1); also the grey between stimuli
    double contrast = 1.0;  // (0, 1]: the noise's amplitude as a fraction of the largest that never
                            // clips for any α (min(mean, 1 − mean) / √2, as |Z| ≤ √2)
};
// InputError naming the parameter (size, tile, correlation, mean, contrast).
void validateStimulus(const StimulusOptions& options);

// The amplitude a of a stimulus: display value = mean + a·Z, Z of eq. 2.24
// with X, Y uniform in [−1, 1); the display standard deviation is a/√3.
double stimulusAmplitude(double mean, double contrast);

// One stimulus: a 1-channel size×size image of display values in [0, 1]
// (never clipped), mean `mean`, standard deviation stimulusAmplitude/√3.
Image stimulusImage(const StimulusOptions& options);

struct StimulusSetOptions {
    int size = 256;                     // small keeps the page small (ranges: stimulusSetMembers())
    std::vector<int> tiles{8, 16, 32};  // each in [1, size], dividing size
    std::vector<double> correlations{0, 0.25, 0.5, 0.75, 1};  // each in [0, 1]
    int repeats = 4;                                          // stimuli per (w, correlation)
    uint32_t seed = 0;                                        // images and trial order
    double mean = 0.5, contrast = 1.0;                        // as StimulusOptions
    int durationMs = 1000;                                    // stimulus shown
    int resetMs = 1000;                                       // mean grey before each stimulus
};
// InputError naming the parameter (size, tiles, correlations, repeats, mean,
// contrast, durationMs, resetMs), and the whole set's work (at most
// kMaxStimulusTrials trials, kMaxStimulusPixels pixels), before any work.
// The entries of StimulusSetOptions' size, repeats and times (its check; the CLI's flags).
std::span<const OptionMember<StimulusSetOptions>> stimulusSetMembers();
constexpr int kMaxStimulusTrials = 5000;
constexpr long long kMaxStimulusPixels = 1ll << 27;
void validateStimulusSet(const StimulusSetOptions& options);

// A permutation of 0 … count−1 drawn from seed (Fisher–Yates over pcg3d).
std::vector<int> stimulusTrialOrder(int count, uint32_t seed);

struct StimulusTrial {
    int trial = 0;         // presentation order, 1-based
    std::string stimulus;  // file name, w<w>_c<correlation>_r<repeat>.png
    int tile = 0;
    double correlation = 0, alpha = 0;
    int repeat = 0;     // 1 … repeats
    uint32_t seed = 0;  // of this image: deriveSeed(seed, 1 + index in the grid order)
};

struct StimulusSet {
    std::vector<StimulusTrial> trials;  // in presentation order
    std::vector<Figure> images;         // the stimuli, same order, file = trial's stimulus (no caption)
    Table listing;                      // stimuli.csv: one row per trial
    std::string page;                   // experiment.html's body: the experiment, images embedded
};
// The grid (w outer, correlation, repeat inner) of stimuli, put in the order
// stimulusTrialOrder(count, deriveSeed(seed, 0)) gives, and the experiment
// page that shows them in that order.
StimulusSet stimulusSet(const StimulusSetOptions& options, const StudyProgress& progress = {});
// Its report: stimuli.csv, the stimuli (not on the page) and experiment.html
// (the experiment, one file, linked from the page).
Report stimulusSetReport(const StimulusSet& set);
inline constexpr const char* kExperimentTitle = "Perception experiment: repeating patterns in noise";

// For a report (Figures 2.13–2.14): one stimulus per (w, correlation) of
// the grid, as a sheet (a row per w), and the correlation measured in each
// between pixels one tile apart (horizontal and vertical pairs) beside the
// asked one, so eq. 2.28 is checked on the very images shown.
struct StimulusOverview {
    Table table;   // overview.csv: w, correlation, α, measured, pairs
    Figure sheet;  // stimuli.png
};
StimulusOverview stimulusOverview(const StimulusSetOptions& options);
// The overview's report (overview.csv, stimuli.png) with the set's
// experiment.html beside it.
Report stimulusOverviewReport(const StimulusOverview& overview, const StimulusSet& set);

// The Pearson correlation between the values one tile (w pixels) apart,
// over every horizontal and vertical pair inside a 1-channel image.
double tileToTileCorrelation(const Image& image, int tile);

}  // namespace stochtex
