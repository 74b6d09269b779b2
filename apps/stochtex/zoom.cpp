// stochtex zoom: frames of the stationary zoom texture (thesis eq. 2.1) as
// PNGs, plus an MP4 where OpenCV's videoio and a codec are available.
#include <cmath>
#include <cstdio>

#include "common.h"
#include "frame_writer.h"
#include "stochtex/core/parallel.h"
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
    addOutputFolderFlag(*cmd, args->dir, "Output folder for frame_NNNN.png (and zoom.mp4)");
    cmd->add_option("--frames", args->frames, "Number of frames")->check(CLI::Range(1, 100000));
    cmd->add_option("--fps", args->fps, "Frames per second (time step 1/fps × speed)");
    cmd->add_option("--speed", args->speed, "Time units t per second of video");
    cmd->add_option("--size", args->size, "Frame size: N or W,H")->delimiter(',')->expected(1, 2);
    cmd->add_flag("--no-video", args->noVideo, "Write PNG frames only");
    addZoomFlags(*cmd, args->zoom);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        if (!(args->fps > 0) || !std::isfinite(args->fps) || args->fps > 1000) throw InputError("--fps must be in (0, 1000]");
        if (!std::isfinite(args->speed)) throw InputError("--speed must be finite");
        const int w = args->size[0], h = args->size.size() > 1 ? args->size[1] : args->size[0];
        if (w < 1 || h < 1 || w > 8192 || h > 8192) throw InputError("--size must be in [1, 8192] per side");
        const ZoomSource source(makeZoomParams(args->zoom), makeZoomBase(args->zoom));
        ensureFolder(args->dir);
        ThreadLimit limit(args->threads);
        FrameSequenceWriter out(args->dir, w, h, args->fps, !args->noVideo);
        const double t0 = source.params().time;
        for (int k = 0; k < args->frames; ++k) {
            out.write(source.render(SourceRegion::centred(w, h), t0 + k / args->fps * args->speed, 0));
            if ((k + 1) % 10 == 0 || k + 1 == args->frames)
                std::fprintf(stderr, "\r[%d/%d] frames", k + 1, args->frames);
        }
        std::fprintf(stderr, "\n");
        if (const std::string mp4 = out.finish(); !mp4.empty()) std::printf("wrote %s\n", mp4.c_str());
        std::printf("wrote %d frames (%dx%d) to %s\n", args->frames, w, h, args->dir.c_str());
    });
}

}  // namespace stochtex::cli
