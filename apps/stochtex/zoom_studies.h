#pragma once
// The thesis studies shared by `zoom`, `correlation`, `contrast` and
// `analyze`: flags describing a stationary zoom texture, and the correlation
// and contrast studies, each writing its images into a folder and returning
// what it wrote (for the report page).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "report.h"
#include "stochtex/textures/zoom_texture.h"

namespace stochtex::cli {

struct ZoomFlags {
    int layers = 8;
    double maxScale = 2.0, time = 0.0, envelopeSigma = 0.3;
    std::string scaling = "exponential", offsets = "none", interpolation = "linear";
    std::string base = "white";  // "white" or an image path
    int baseSize = 512;          // white-noise lattice period
    uint32_t seed = 1;
};
void addZoomFlags(CLI::App& cmd, ZoomFlags& f, bool withLayers = true);
ZoomParams makeZoomParams(const ZoomFlags& f);
// The base lattice of instance `instance` (white noise: a seed per instance;
// an image: the image itself, every instance alike).
LatticeTexture makeBase(const ZoomFlags& f, int instance = 0);

struct StudyOutput {
    std::vector<Figure> figures;
    std::string table;  // Markdown/plain summary of the numbers
};

struct CorrelationStudy {
    std::vector<std::string> variants{"sliding", "fixed", "simple", "random"};
    std::vector<int> layers{16, 8, 4, 2};
    int instances = 512;
    int size = 128;  // plots cover x, y ∈ [0, size) pixels from the zoom centre
};
StudyOutput runCorrelationStudy(const ZoomFlags& flags, const CorrelationStudy& study, const std::string& dir);

struct ContrastStudy {
    int size = 512;
    int layers = 16;
};
// InputError for unusable flags or study settings, before anything is written.
void validateStudy(const ZoomFlags& flags, const CorrelationStudy& study);
void validateStudy(const ZoomFlags& flags, const ContrastStudy& study);

StudyOutput runContrastStudy(const ZoomFlags& flags, const ContrastStudy& study, const std::string& dir);

}  // namespace stochtex::cli
