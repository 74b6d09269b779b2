#include "shadertoy_flags.h"

#include <algorithm>
#include <cstdio>
#include <regex>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/page.h"
#include "stochtex/report/plot.h"

namespace stochtex::cli {

std::string shadertoyDateText(const std::array<int, 6>& d) {
    char text[32];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d", d[0], d[1], d[2], d[3], d[4], d[5]);
    return text;
}

void addShadertoyFlags(CLI::App& cmd, ShadertoyFlags& f) {
    CLI::Option* size = cmd.add_option("--size", f.size, "Frame size, iResolution: N or W,H")
                            ->delimiter(',')
                            ->expected(1, 2)
                            ->default_str(std::to_string(f.size[0]) + "," + std::to_string(f.size[1]));
    bindParameter(cmd, size, "width");
    bindParameter(cmd, size, "height");
    bindParameter(cmd, cmd.add_option("--time", f.time, "iTime of frame 0, seconds")->capture_default_str(),
                  "startTime");
    cmd.add_option("--fps", f.fps, "Frames per second: iFrameRate, iTimeDelta = 1/fps, video rate")
        ->capture_default_str();
    cmd.add_option("--mouse", f.mouse,
                   "iMouse: X,Y (the button pressed there at frame 0 and held, with ShaderToy's "
                   "click semantics) or X,Y,CLICK_X,CLICK_Y (iMouse as given, every frame), "
                   "pixels, y up")
        ->delimiter(',')
        ->expected(2, 4);
    cmd.add_option("--date", f.date, "iDate at iTime 0: YYYY-MM-DD or YYYY-MM-DDTHH:MM:SS")->capture_default_str();
    cmd.add_option("--keys", f.keys, "Key codes held from frame 0 (JavaScript keyCode, e.g. 65 for A), comma-separated")
        ->delimiter(',');
    cmd.add_option("--input", f.inputFile,
                   "A timeline of key and mouse events at frames or times (JSON; "
                   "docs/SHADERTOY.md), replayed from frame 0");
    cmd.add_option("--event", f.events,
                   "One event: FRAME:keydown:CODE, FRAME:keyup:CODE, FRAME:mousedown:X,Y, "
                   "FRAME:mousemove:X,Y or FRAME:mouseup; FRAME a frame or a time (1.5s); "
                   "repeat the flag for more")
        ->take_all();
    cmd.add_option("--hw-performance", f.hwPerformance,
                   "HW_PERFORMANCE, which shaders test to pick their quality: 1 (ShaderToy on a desktop) or 0 (on a "
                   "phone)")
        ->capture_default_str();
    cmd.add_option("--first-frame", f.firstFrame,
                   "The frame a study starts at (the frames before it are rendered "
                   "too: buffers with feedback need them); default 0");
}

ShadertoySettings shadertoySettings(const CLI::App& cmd, const ShadertoyFlags& f) {
    ShadertoySettings s;
    s.width = f.size[0];
    s.height = f.size.size() > 1 ? f.size[1] : f.size[0];
    s.startTime = f.time;
    s.fps = f.fps;
    if (f.mouse.size() == 3) refuseOption(cmd, "--mouse", "give X,Y or X,Y,CLICK_X,CLICK_Y, got 3 numbers");
    if (f.mouse.size() == 4)
        for (size_t k = 0; k < 4; ++k) s.mouse[k] = f.mouse[k];
    const std::regex date(R"((\d{4})-(\d{2})-(\d{2})(?:T(\d{2}):(\d{2}):(\d{2}))?)");
    std::smatch m;
    if (!std::regex_match(f.date, m, date))
        refuseOption(cmd, "--date", "expected YYYY-MM-DD or YYYY-MM-DDTHH:MM:SS, got \"" + f.date + "\"");
    for (int k = 0; k < 6; ++k) s.date[size_t(k)] = m[k + 1].matched ? std::stoi(m[k + 1].str()) : 0;
    s.keys = f.keys;
    s.hwPerformance = f.hwPerformance;
    if (f.firstFrame < 0 || f.firstFrame > 1000000)
        refuseOption(cmd, "--first-frame", "must be in [0, 1000000], got " + std::to_string(f.firstFrame));
    validateShadertoySettings(s);
    // The timeline: the --mouse press, the file's events, the --event ones; in order of frame (stable).
    if (f.mouse.size() == 2) s.inputs.push_back({0, ShadertoyInput::Kind::MouseDown, 0, f.mouse[0], f.mouse[1]});
    if (!f.inputFile.empty()) {
        const std::vector<ShadertoyInput> file = loadShadertoyInputs(f.inputFile, s.fps, s.startTime);
        s.inputs.insert(s.inputs.end(), file.begin(), file.end());
    }
    for (const std::string& e : f.events) s.inputs.push_back(parseShadertoyInputText(e, s.fps, s.startTime));
    std::stable_sort(s.inputs.begin(), s.inputs.end(),
                     [](const ShadertoyInput& a, const ShadertoyInput& b) { return a.frame < b.frame; });
    validateShadertoySettings(s);
    return s;
}

Inspect parseInspect(const CLI::App& cmd, const std::string& text) {
    if (text.empty()) return {};
    const std::regex form(R"(([a-z_]+):(\d{1,5}),(\d{1,5}))");
    std::smatch m;
    if (!std::regex_match(text, m, form))
        refuseOption(cmd, "--inspect", "expected PASS:X,Y (e.g. buffer_a:10,20), got \"" + text + "\"");
    return {m[1].str(), std::stoi(m[2].str()), std::stoi(m[3].str())};
}

void printInspect(const ShadertoyHost& host, const Inspect& in) {
    const std::array<float, 4> v = host.pixel(in.pass, in.x, in.y);
    std::printf("%s (%d, %d) at iFrame %d: %.9g %.9g %.9g %.9g\n", in.pass.c_str(), in.x, in.y, host.frame() - 1,
                double(v[0]), double(v[1]), double(v[2]), double(v[3]));
}

Image clampedFrame(const Image& frame) {
    Image out = frame;
    for (float& v : out.data()) v = std::clamp(v, 0.0f, 1.0f);
    return out;
}

namespace {

void checkSheet(const CLI::App& cmd, int frames, int width, int height) {
    // sheet() draws on at most 16384 pixels a side; eight frames a row, their captions below.
    const int columns = std::min(frames, 8), rows = (frames + 7) / 8;
    if (frames < 1 || frames > 64) refuseOption(cmd, "--sheet", "shows 1 to 64 frames, got " + std::to_string(frames));
    if ((long long)columns * (width + 16) > 16000 || (long long)rows * (height + 64) > 16000)
        refuseOption(cmd, "--sheet",
                     std::to_string(frames) + " frames of " + std::to_string(width) + "x" + std::to_string(height) +
                         " make a sheet over 16000 pixels a side; use a smaller --size");
}

}  // namespace

FrameOutputs::FrameOutputs(const CLI::App& cmd, std::string output, bool sheet, int frames,
                           const ShadertoySettings& settings)
    : output_(std::move(output)),
      sheet_(sheet),
      image_(!output_.empty() && isSupportedImagePath(output_)),
      settings_(settings) {
    if (frames < 1 || frames > 1000000)
        refuseOption(cmd, "--frames", "must be in [1, 1000000], got " + std::to_string(frames));
    if (sheet_ && !image_) refuseOption(cmd, "--sheet", "needs an image output");
    if (image_) checkImageOutput(output_);
    // Refused before any frame is rendered: an extension that is neither an
    // image nor a sequence's (a folder has none).
    if (!output_.empty() && !image_) try {
            sequenceFormat(output_);
        } catch (const InputError&) {
            refuseOption(cmd, "--output",
                         output_ + ": expected an image (" + kImageOutputFormats + ") or " + kSequenceOutputHelp);
        }
    if (sheet_) checkSheet(cmd, frames, settings.width, settings.height);
}

ShadertoyFrameSink FrameOutputs::sink() {
    return [this](int frame, const Image& img) {
        if (output_.empty()) return;
        if (!image_) {
            if (!sequence_)
                sequence_ = std::make_unique<FrameSequenceWriter>(output_, settings_.width, settings_.height,
                                                                  settings_.fps, "", Transfer::Linear);
            sequence_->write(clampedFrame(img));
            return;
        }
        if (!sheet_) frames_.clear();
        frames_.push_back(img);
        captions_.push_back("iFrame " + std::to_string(frame));
    };
}

FrameReadBack FrameOutputs::readBack() const {
    if (output_.empty()) return FrameReadBack::None;
    return image_ && !sheet_ ? FrameReadBack::Last : FrameReadBack::Every;
}

std::string FrameOutputs::finish() {
    if (output_.empty()) return "";
    if (!image_) {
        if (!sequence_) return "";
        const std::string video = sequence_->finish();
        return isVideoPath(output_) ? video : output_;  // the MP4 moved into place, or the folder of frames
    }
    if (sheet_) {
        std::vector<std::vector<Image>> rows;
        std::vector<std::vector<std::string>> text;
        for (size_t k = 0; k < frames_.size(); ++k) {
            if (k % 8 == 0) rows.emplace_back(), text.emplace_back();
            rows.back().push_back(clampedFrame(frames_[k]));
            text.back().push_back(captions_[k]);
        }
        writeImage(output_, sheet(rows, text), kNoTransfer);
    } else {
        writeImage(output_, frames_.back(), kNoTransfer);
    }
    return output_;
}

void addFrameAnalysisFlags(CLI::App& cmd, FrameAnalysisFlags& f) {
    // The analyses' time step is 1/fps (addShadertoyFlags' --fps, added
    // before): their errors about it name --fps. Only here: a program as a
    // study's source (flow ... shadertoy) takes its time step from the
    // study's own --dt.
    if (CLI::Option* fps = cmd.get_option_no_throw("--fps")) bindParameter(cmd, fps, "timeStep");
    bindParameter(cmd,
                  cmd.add_option("--analyse", f.list,
                                 "Studies of the frames, comma-separated: spectrum (the first), flow, coherence, "
                                 "flicker, statistics (over instances); -o is then the report's folder"),
                  "analyses");
    f.instancesOption = cmd.add_option("--instances", f.instances,
                                       "statistics: instances 0..N-1 through the program's instance uniform")
                            ->capture_default_str();
    cmd.add_option("--point", f.point,
                   "statistics: the correlation's point X,Y in pixels from the top left "
                   "(default the centre)")
        ->delimiter(',')
        ->expected(2);
}

FrameAnalysisOptions frameAnalysisOptions(const CLI::App& cmd, const FrameAnalysisFlags& flags,
                                          const ShadertoySettings& settings, int frames, int firstFrame) {
    FrameAnalysisOptions o;
    std::string rest = flags.list;
    while (!rest.empty()) {
        const size_t comma = rest.find(',');
        const std::string name = rest.substr(0, comma);
        const FrameAnalysis* a = findEnum(kFrameAnalysisNames, name);
        if (!a)
            refuseOption(cmd, "--analyse",
                         "unknown study \"" + name + "\" (expected " + canonicalNames(kFrameAnalysisNames, ", ") + ")");
        o.analyses.push_back(*a);
        rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    }
    const bool statistics = std::count(o.analyses.begin(), o.analyses.end(), FrameAnalysis::Statistics) > 0;
    refuseWithoutEffect(flags.instancesOption, statistics, "without statistics in --analyse");
    refuseWithoutEffect(cmd.get_option("--point"), statistics, "without statistics in --analyse");
    o.instances = flags.instances;
    if (!flags.point.empty()) o.pointX = flags.point[0], o.pointY = flags.point[1];
    o.region = SourceRegion::centred(settings.width, settings.height);
    o.time = settings.startTime + firstFrame / settings.fps;
    o.timeStep = 1.0 / settings.fps;
    o.frames = frames;
    o.frameTransfer = Transfer::Linear;  // ShaderToy's frames are display codes already
    return o;
}

}  // namespace stochtex::cli
