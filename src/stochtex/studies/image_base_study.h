#pragma once
// Image textures as the base of the stationary zoom texture (thesis §2.7.1,
// Figures 2.15–2.17): each image's own correlation around a reference
// point (over periodic translations of it: ImageTextureSource), then the
// zoom texture over it without offsets and with hashed offsets, each with
// its correlation map. Textures with regular structure keep echoes of it
// (ghosting) that the offsets cannot remove; stochastic ones keep their look.
#include <span>
#include <string>
#include <vector>

#include "stochtex/pattern/param_info.h"
#include "stochtex/report/page.h"
#include "stochtex/report/table.h"
#include "stochtex/studies/paper.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex {

struct ImageBase {
    std::string name;
    Image image;  // any channels: gray by the thesis's luminosity formula (toGray)
};

struct ImageBaseStudyOptions {
    ZoomParams zoom;      // the layers (Figure 2.17: 8) and scales; offsets are set per variant
    int size = 128;       // frame and correlation-map side (ranges: imageBaseStudyMembers())
    int instances = 256;  // translations of the image averaged
    // The reference point of the correlation maps, in frame pixels (Figure
    // 2.15 takes it in the bottom-right quadrant); negative: 3/4 of the size.
    int referenceX = -1, referenceY = -1;
    int echoRadius = 4;  // the echo figure ignores correlations within this many pixels of the reference
};
// The entries of ImageBaseStudyOptions' numbers (its check; the CLI's flags).
std::span<const OptionMember<ImageBaseStudyOptions>> imageBaseStudyMembers();
// InputError naming the parameter (size, instances, referenceX, …).
void validateImageBaseStudy(const ImageBaseStudyOptions& options, const std::vector<ImageBase>& images);

struct ImageBaseStudyResult {
    // Per image: the base, the zoom texture without offsets and with hashed
    // offsets; the largest correlation farther than echoRadius from the
    // reference point (the strongest echo) of each.
    Table table;
    std::vector<Figure> figures;  // figure2_15.png, figure2_17.png
};
ImageBaseStudyResult imageBaseStudy(const std::vector<ImageBase>& images, const ImageBaseStudyOptions& options,
                                    const StudyProgress& progress = {});
// Its report (thesis §2.7.1): fractalize.csv and Figures 2.15 and 2.17.
Report imageBaseReport(const ImageBaseStudyResult& result);

}  // namespace stochtex
