#pragma once
// The flags describing a stationary zoom texture, shared by `zoom`,
// `correlation`, `contrast` and `analyze`.
#include <CLI/CLI.hpp>
#include <string>

#include "common.h"

#include "stochtex/studies/artifact_report.h"

namespace stochtex::cli {

struct ZoomFlags {
    ZoomParams params;           // the defaults of ZoomParams are the flags' defaults
    std::string base = "white";  // "white" or an image path
    ZoomBase lattice;            // the white-noise lattice's period (its defaults are the flags')
    uint32_t seed = 1;
};
void addZoomFlags(CLI::App& cmd, ZoomFlags& f, bool withLayers = true);

// What a command of a zoom-texture study holds: the texture's flags, the
// study's options, its output folder and --threads.
template <class Study>
struct ZoomStudyArgs {
    ZoomFlags zoom;
    Study study;
    std::string dir;
    int threads = 0;
};
// The zoom flags (withLayers: --layers too) and --threads of a study command.
template <class Study>
void addZoomStudyFlags(CLI::App& cmd, ZoomStudyArgs<Study>& args, bool withLayers) {
    addZoomFlags(cmd, args.zoom, withLayers);
    addThreadsFlag(cmd, args.threads);
}
// InputError for unusable values (naming the flag), before any work.
ZoomParams makeZoomParams(const ZoomFlags& f);
ZoomBase makeZoomBase(const ZoomFlags& f);

// --instances, --layers-list, the plot size (sizeFlag) and, withVariants,
// --variant of the correlation study.
void addCorrelationStudyFlags(CLI::App& cmd, CorrelationStudyOptions& study, const std::string& sizeFlag = "--size",
                              bool withVariants = true);

}  // namespace stochtex::cli
