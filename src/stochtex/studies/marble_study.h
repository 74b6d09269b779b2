#pragma once
// The marble texture's artifacts (thesis §2.7.2 and §2.8, Figures 1.6 and
// 2.19–2.24), each compared between the naive continuous scaling and its fix:
//   * stretching: l varies along x; the texture, its perturbation and the
//     scaling step alone, with the local anisotropy of the noise coordinates;
//   * correlation around a point over instances (seeds): the marble's, the
//     base gradient noise's (its anti-correlated lobes, Figure 2.21) and the
//     scaling step's alone (white cell noise through the same scaling, which
//     separates the artifact from the noise's own correlation), with their
//     shapes (analysis/correlation_shape.h);
//   * power spectra of the marble and of the scaled noise: the anisotropy
//     that stretching adds (Figure 2.22);
//   * sliding: l grows with time; optical flow of the frames, whose outward
//     motion the fix removes (Figures 2.23–2.24).
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "stochtex/analysis/optical_flow.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/marble_texture.h"

namespace stochtex {

struct MarbleStudyOptions {
    MarbleParams marble;  // the texture; each panel sets the scaling and the layer, sliding its own law of l
    std::vector<MarbleScaling> scalings{MarbleScaling::Continuous, MarbleScaling::BlendedCorrected};
    int size = 256;  // frames of size × size pixels centred on the origin (ranges: marbleStudyMembers())
    // Correlation: a correlationSize² window centred on the reference point,
    // in pixels from the origin. NaN: x = −period/4 of l, where l changes
    // fastest along x, and y halfway from the axis to the frames' edge (less
    // the window): where the scaling x / 2^l(x) shears the noise's cells
    // into long slanted ones (marbleAnisotropy).
    int correlationSize = 96;
    double pointX = std::numeric_limits<double>::quiet_NaN(), pointY = std::numeric_limits<double>::quiet_NaN();
    int instances = 256;        // seeds per correlation map
    int spectrumInstances = 8;  // seeds per spectrum
    // Sliding: l = m + r t with r = slideRate (n = 0), frames at kΔt.
    double slideRate = 1;
    int frames = 48;
    double timeStep = 1.0 / 24;
    int flowStep = 16;  // pixels between the flow vectors
    // DIS: Farnebäck's small polynomial windows underestimate the motion of
    // the smooth scaled noise (cells of 32–128 pixels) several-fold, where
    // DIS and Lucas–Kanade recover the scaling's rate within a few percent.
    FlowMethod flowMethod = FlowMethod::Dis;
};
// The entries of MarbleStudyOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<MarbleStudyOptions>> marbleStudyMembers();
// InputError naming the parameter, before any work.
void validateMarbleStudy(const MarbleStudyOptions& options);

// How much the continuous scaling u = x / 2^l(x) distorts the noise at
// (x, y): the ratio σ₁/σ₂ of the singular values of its Jacobian
// 2^−l [[s, 0], [g, 1]], s = 1 − x ln 2 ∂l/∂x, g = −y ln 2 ∂l/∂x (1: the
// noise only scaled; ∞ where s = 0, the folds where the texture is
// mirrored). A cell of the scaled lattice is about that much longer than
// wide. The blended scalings have 1 everywhere.
double marbleAnisotropy(const MarbleParams& params, double x, double y);

struct MarbleStudyResult {
    double pointX = 0, pointY = 0;  // the correlation reference used
    double pointAnisotropy = 1;     // marbleAnisotropy there
    Table correlation;              // correlation.csv: layer × scaling, the maps' shapes
    Table spectra;                  // spectra.csv: layer × scaling, anisotropy
    Table sliding;  // sliding.csv: layer (marble, scaled noise) × scaling, the mean flow figures beside the scaling's
                    // own rate
    std::vector<Figure> figures;
    std::vector<std::string> videos;  // marbleVideoNames
};
// The sliding sequences' names, one per scaling (sliding_<scaling>), in the
// order a sink receives them: the names of their files.
std::vector<std::string> marbleVideoNames(const MarbleStudyOptions& options);
// onFrame(video, k, frame): every sliding frame, video by video (the index
// into marbleVideoNames), values in [0, 1], options.size² pixels.
using MarbleFrameSink = std::function<void(size_t, int, const Image&)>;
MarbleStudyResult marbleStudy(const MarbleStudyOptions& options, const StudyProgress& progress = {},
                              const MarbleFrameSink& onFrame = {});

// The report's section on the study (figures under `prefix`, e.g. "marble/";
// `videos` true: an animated <name>.webp per sliding video beside them).
Report marbleReport(const MarbleStudyResult& result, bool videos);

}  // namespace stochtex
