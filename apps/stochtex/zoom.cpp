// stochtex zoom: frames of the stationary zoom texture (thesis eq. 2.1) as
// PNGs, plus an MP4 where OpenCV's videoio and a codec are available.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "common.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "zoom_flags.h"

#if __has_include(<opencv2/videoio.hpp>) && defined(STOCHTEX_HAVE_VIDEOIO)
#include <opencv2/videoio.hpp>
#define STOCHTEX_VIDEO 1
#endif

namespace stochtex::cli {
namespace fs = std::filesystem;

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
    cmd->add_option("-o,--output", args->dir, "Output folder for frame_NNNN.png (and zoom.mp4)")->required();
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
#ifdef STOCHTEX_VIDEO
        cv::VideoWriter video;
        const std::string mp4 = (fs::path(args->dir) / "zoom.mp4").string();
        const std::string partial = mp4 + ".partial.mp4";
        if (!args->noVideo)
            video.open(partial, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), args->fps, cv::Size(w, h), false);
        if (!args->noVideo && !video.isOpened())
            std::fprintf(stderr, "note: no MP4 encoder available in this OpenCV build; writing PNG frames only\n");
#else
        if (!args->noVideo)
            std::fprintf(stderr, "note: built without OpenCV videoio (Debian: libopencv-videoio-dev); "
                                 "writing PNG frames only\n");
#endif
        const double t0 = source.params().time;
        for (int k = 0; k < args->frames; ++k) {
            const Image frame = source.render(SourceRegion::centred(w, h), t0 + k / args->fps * args->speed, 0);
            char name[32];
            std::snprintf(name, sizeof name, "frame_%04d.png", k);
            writeImage((fs::path(args->dir) / name).string(), frame);
#ifdef STOCHTEX_VIDEO
            if (video.isOpened()) {
                cv::Mat m(h, w, CV_8UC1);
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x)
                        m.at<uchar>(y, x) = uchar(std::lround(255.0 * std::clamp(frame.at(x, y), 0.0f, 1.0f)));
                video.write(m);
            }
#endif
            if ((k + 1) % 10 == 0 || k + 1 == args->frames)
                std::fprintf(stderr, "\r[%d/%d] frames", k + 1, args->frames);
        }
        std::fprintf(stderr, "\n");
#ifdef STOCHTEX_VIDEO
        if (video.isOpened()) {
            video.release();
            fs::rename(partial, mp4);
            std::printf("wrote %s\n", mp4.c_str());
        }
#endif
        std::printf("wrote %d frames (%dx%d) to %s\n", args->frames, w, h, args->dir.c_str());
    });
}

}  // namespace stochtex::cli
