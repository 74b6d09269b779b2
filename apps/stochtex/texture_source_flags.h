#pragma once
// The texture a frame study (`spectrum`, `flow`, `coherence`) analyses, chosen by a
// sub-command of it, so each source keeps its own flags:
//   CMD images FILE...    image files: frames of a sequence (or instances)
//   CMD pattern ...       a pattern (--preset / --pattern), unfiltered or --filter
//   CMD zoom ...          the stationary zoom texture (the zoom command's flags)
//   CMD marble ...        the marble texture (the marble command's texture flags, --scaling, --layer)
//   CMD shadertoy PROG    a ShaderToy program's frames (the shadertoy command's flags)
// The study's own flags stay on CMD, before the sub-command.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "stochtex/image/colour_space.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex::cli {

// What the study needs to know of the source beside its frames.
struct SourceInfo {
    std::string name;
    bool images = false;   // an ImageSequenceSource: windows at (0, 0), frames = files
    int frames = 0;        // image files given (images only)
    int width = 0, height = 0;  // the files' size (images only)
    Transfer transfer = Transfer::Linear;  // how its frames are shown (Srgb: linear colour renders)
    double time = 0;  // the first frame's time (zoom: --time)
};
using SourceStudy = std::function<void(const TextureSource& source, const SourceInfo& info)>;

// Adds the four sub-commands to cmd (one is required); the chosen one builds
// its source (InputError naming the flag or file on bad input) and calls study.
void addTextureSourceCommands(CLI::App& cmd, SourceStudy study);

// --size N or W,H: the window a study takes of a pattern, the zoom or the
// marble texture (image files are analysed whole). Default 256.
struct WindowSizeFlag {
    std::vector<int> size{256};
    const CLI::Option* option = nullptr;
};
// `what` starts the help: "Window size", "Frame size".
void addWindowSizeFlag(CLI::App& cmd, WindowSizeFlag& flag, const std::string& what);
// The region the study analyses: image files' whole size (--size refused
// with them: "has no effect `onImages`"), else the --size window, centred.
SourceRegion studyRegion(const WindowSizeFlag& flag, const SourceInfo& info, const std::string& onImages);

}  // namespace stochtex::cli
