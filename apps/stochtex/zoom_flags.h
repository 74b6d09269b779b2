#pragma once
// The flags describing a stationary zoom texture, shared by `zoom`,
// `correlation`, `contrast` and `analyze`.
#include <CLI/CLI.hpp>
#include <string>

#include "stochtex/studies/zoom_studies.h"

namespace stochtex::cli {

struct ZoomFlags {
    ZoomParams params;           // the defaults of ZoomParams are the flags' defaults
    std::string base = "white";  // "white" or an image path
    int baseSize = 512;          // white-noise lattice period
    uint32_t seed = 1;
};
void addZoomFlags(CLI::App& cmd, ZoomFlags& f, bool withLayers = true);
// InputError for unusable values (naming the flag), before any work.
ZoomParams makeZoomParams(const ZoomFlags& f);
ZoomBase makeZoomBase(const ZoomFlags& f);

// --instances, --layers-list, the plot size (sizeFlag) and, withVariants,
// --variant of the correlation study.
void addCorrelationStudyFlags(CLI::App& cmd, CorrelationStudyOptions& study, const std::string& sizeFlag = "--size",
                              bool withVariants = true);

// The contrast study of the zoom texture the flags describe, written into
// dir (figures and contrast.csv); shared by `contrast` and `analyze`.
ContrastStudyResult runZoomContrastStudy(const ZoomFlags& flags, const ContrastStudyOptions& study,
                                         const std::string& dir);

}  // namespace stochtex::cli
