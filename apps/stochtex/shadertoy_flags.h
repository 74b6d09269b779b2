#pragma once
// The flags of a ShaderToy program's run (`shadertoy`, and the `shadertoy`
// texture source of spectrum, flow and coherence): size, time, fps, mouse,
// date and keys, to ShadertoySettings; --inspect's PASS:X,Y.
#include <CLI/CLI.hpp>

#include <array>
#include <string>
#include <vector>

#include "stochtex/gpu/shadertoy.h"
#include "stochtex/report/frame_sequence.h"
#include "stochtex/studies/frame_analysis.h"

namespace stochtex::cli {

// "YYYY-MM-DDTHH:MM:SS", the form --date takes.
std::string shadertoyDateText(const std::array<int, 6>& date);

// The flags start at the library's defaults (ShadertoySettings), which the help shows.
struct ShadertoyFlags {
    std::vector<int> size{ShadertoySettings{}.width, ShadertoySettings{}.height};
    double time = ShadertoySettings{}.startTime, fps = ShadertoySettings{}.fps;
    std::vector<float> mouse;
    std::string date = shadertoyDateText(ShadertoySettings{}.date);
    std::vector<int> keys;
    std::string inputFile;            // --input: a timeline of key and mouse events (gpu/shadertoy_input.h)
    std::vector<std::string> events;  // --event FRAME:EVENT[:VALUE], repeated
    int firstFrame = 0;               // the first frame a study analyses
    int hwPerformance = ShadertoySettings{}.hwPerformance;
};
void addShadertoyFlags(CLI::App& cmd, ShadertoyFlags& flags);
// The settings the flags give; InputError naming the flag when unusable.
ShadertoySettings shadertoySettings(const CLI::App& cmd, const ShadertoyFlags& flags);

struct Inspect {
    std::string pass;  // empty: nothing to inspect
    int x = 0, y = 0;
};
// "PASS:X,Y" (empty: none); InputError naming --inspect otherwise.
Inspect parseInspect(const CLI::App& cmd, const std::string& text);
// Prints "PASS (X, Y) at iFrame N: r g b a".
void printInspect(const ShadertoyHost& host, const Inspect& inspect);

// A frame for 8-bit outputs: every value clamped to [0, 1] (a shader may write any float).
Image clampedFrame(const Image& frame);
// Where `shadertoy` writes its frames, by the output's form: an image (the
// last frame, or with `sheet` a contact sheet of all), an MP4 or a folder of
// frames. Everything is checked on construction, before any work; nothing
// is created before the first frame.
class FrameOutputs {
public:
    // cmd: the command with --output, --frames and --sheet, which its errors name.
    FrameOutputs(const CLI::App& cmd, std::string output, bool sheet, int frames, const ShadertoySettings& settings);
    ShadertoyFrameSink sink();
    // The frames the sink takes: every one for a sheet, a video or a
    // folder, the last for an image, none without an output.
    FrameReadBack readBack() const;
    // Writes the image or closes the video; the path written ("" for none).
    std::string finish();

private:
    std::string output_;
    bool sheet_, image_;
    ShadertoySettings settings_;
    std::unique_ptr<FrameSequenceWriter> sequence_;
    std::vector<Image> frames_;
    std::vector<std::string> captions_;
};

// --analyse LIST (the studies), --instances N and --point X,Y (statistics).
struct FrameAnalysisFlags {
    std::string list;
    int instances = FrameAnalysisOptions{}.instances;
    std::vector<int> point;
    const CLI::Option* instancesOption = nullptr;
};
void addFrameAnalysisFlags(CLI::App& cmd, FrameAnalysisFlags& flags);
// The studies over --frames frames from --first-frame, the whole frame as
// the window; InputError naming the flag: an unknown study, --instances or
// --point without statistics (a program without an instance uniform is
// refused by the study itself, ShadertoySource::checkInstances).
FrameAnalysisOptions frameAnalysisOptions(const CLI::App& cmd, const FrameAnalysisFlags& flags,
                                          const ShadertoySettings& settings, int frames, int firstFrame);
// The report: figures, CSV tables and index.html in dir.

}  // namespace stochtex::cli
