#include "frame_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "stochtex/image/image_io.h"

#if __has_include(<opencv2/videoio.hpp>) && defined(STOCHTEX_HAVE_VIDEOIO)
#include <opencv2/videoio.hpp>
#define STOCHTEX_VIDEO 1
#endif

namespace stochtex::cli {
namespace fs = std::filesystem;

struct FrameSequenceWriter::Video {
#ifdef STOCHTEX_VIDEO
    cv::VideoWriter writer;
    std::string path, partial;
#endif
};

FrameSequenceWriter::FrameSequenceWriter(const std::string& dir, int width, int height, double fps, bool video)
    : dir_(dir), video_(std::make_unique<Video>()) {
#ifdef STOCHTEX_VIDEO
    video_->path = (fs::path(dir) / "zoom.mp4").string();
    video_->partial = video_->path + ".partial.mp4";
    if (video)
        video_->writer.open(video_->partial, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps, cv::Size(width, height),
                            false);
    if (video && !video_->writer.isOpened())
        std::fprintf(stderr, "note: no MP4 encoder available in this OpenCV build; writing PNG frames only\n");
#else
    (void)width, (void)height, (void)fps;
    if (video)
        std::fprintf(stderr, "note: built without OpenCV videoio (Debian: libopencv-videoio-dev); "
                             "writing PNG frames only\n");
#endif
}

FrameSequenceWriter::~FrameSequenceWriter() = default;

void FrameSequenceWriter::write(const Image& frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", count_++);
    writeImage((fs::path(dir_) / name).string(), frame);
#ifdef STOCHTEX_VIDEO
    if (!video_->writer.isOpened()) return;
    cv::Mat m(frame.height(), frame.width(), CV_8UC1);
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x)
            m.at<uchar>(y, x) = uchar(std::lround(255.0 * std::clamp(frame.at(x, y), 0.0f, 1.0f)));
    video_->writer.write(m);
#endif
}

std::string FrameSequenceWriter::finish() {
#ifdef STOCHTEX_VIDEO
    if (video_->writer.isOpened()) {
        video_->writer.release();
        fs::rename(video_->partial, video_->path);
        return video_->path;
    }
#endif
    return "";
}

}  // namespace stochtex::cli
