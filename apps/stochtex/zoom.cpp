// stochtex zoom: frames of the stationary zoom texture (thesis eq. 2.1) as
// PNGs plus zoom.mp4 in a folder, or one file by -o's extension (.mp4, .webm, .webp, .gif).
#include <charconv>
#include <cmath>
#include <cstdio>

#include "common.h"
#include "progress.h"
#include "stochtex/core/parallel.h"
#include "stochtex/report/frame_sequence.h"
#include "zoom_flags.h"

namespace stochtex::cli {

void registerZoom(CLI::App& app) {
    struct Args {
        ZoomFlags zoom;
        std::string dir;
        int frames = 60, threads = 0;
        double fps = 30, speed = 0.25;
        std::vector<int> size{512};
        bool noVideo = false;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("zoom", "Frames of the stationary zoom texture (thesis eq. 2.1, 2.2, 2.5)");
    addOutputFolderFlag(*cmd, args->dir,
                        std::string("Output: a folder for frame_NNNN.png and zoom.mp4 (H.264; an interrupted run "
                                    "leaves the frames written so far), or one file: ") +
                            kSequenceOutputHelp);
    cmd->add_option("--frames", args->frames, "Number of frames")->check(CLI::Range(1, 100000));
    const CLI::Option* fps = cmd->add_option("--fps", args->fps, "Frames per second (time step 1/fps × speed)");
    const CLI::Option* speed = cmd->add_option("--speed", args->speed, "Time units t per second of video");
    const CLI::Option* size =
        cmd->add_option("--size", args->size, "Frame size: N or W,H")->delimiter(',')->expected(1, 2);
    const CLI::Option* noVideo = cmd->add_flag("--no-video", args->noVideo, "Write PNG frames only (into a folder)");
    addZoomFlags(*cmd, args->zoom);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args, cmd, fps, speed, size, noVideo] {
        if (!(args->fps > 0) || !std::isfinite(args->fps) || args->fps > 1000)
            refuseOption(fps, "fps must be in (0, 1000], got " + formatValue(args->fps));
        if (!std::isfinite(args->speed)) refuseOption(speed, "speed must be finite, got " + formatValue(args->speed));
        const auto [w, h] = sizeFlagValue(size, args->size, 8192);
        if (args->noVideo && isVideoPath(args->dir))
            refuseOption(noVideo, "-o " + args->dir + " is one file of frames, not a folder");
        const ZoomSource source(makeZoomParams(args->zoom), makeZoomBase(args->zoom));
        const double t0 = source.params().time;
        const auto frameTime = [&](int k) { return t0 + k / args->fps * args->speed; };
        // Times grow (or shrink) with k, so the last frame's bounds them all:
        // checked before anything is written.
        ZoomParams last = source.params();
        last.time = frameTime(args->frames - 1);
        try {
            validateZoomParams(last);
        } catch (const InputError& e) {
            // Shortest round-trip digits: 1e9 + 1/60 must not print as 1e+09.
            char t[32];
            *std::to_chars(t, t + sizeof t - 1, last.time).ptr = '\0';
            refuseOption(cmd->get_option("--time"),
                         "with --speed, --fps and --frames, the last frame would be at t = --time + (frames − 1) / "
                         "fps × speed = " +
                             std::string(t) + ", out of range: " + e.what());
        }
        ThreadLimit limit(args->threads);
        // Zoom-texture values are data (thesis eq. 2.1), written as they are.
        FrameSequenceWriter out(args->dir, w, h, args->fps, args->noVideo ? "" : "zoom.mp4", Transfer::Linear);
        ProgressLine progress("zoom");
        for (int k = 0; k < args->frames; ++k) {
            progress.update(double(k) / args->frames,
                            "frame " + std::to_string(k + 1) + "/" + std::to_string(args->frames));
            out.write(source.render(SourceRegion::centred(w, h), frameTime(k), 0));
        }
        progress.update(1.0, "finishing the video");
        const std::string mp4 = out.finish();
        progress.finish();
        if (!mp4.empty()) std::printf("wrote %s\n", mp4.c_str());
        if (!isVideoPath(args->dir))
            std::printf("wrote %d frames (%dx%d) to %s\n", args->frames, w, h, args->dir.c_str());
    });
}

}  // namespace stochtex::cli
