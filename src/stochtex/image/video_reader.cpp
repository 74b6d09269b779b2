#include "stochtex/image/video_reader.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>

#include "stochtex/core/error.h"
#include "stochtex/image/media_codecs.h"

namespace stochtex {

VideoReader::VideoReader(const std::string& path) : path_(path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": video not found");
    open();
    const VideoDecoder& video = *video_;
    const double width = video.width(), height = video.height();
    width_ = std::isfinite(width) && std::abs(width) < 1e9 ? int(width) : 0;
    height_ = std::isfinite(height) && std::abs(height) < 1e9 ? int(height) : 0;
    fps_ = video.fps();
    const double count = video.frameCount();
    frameCount_ = std::isfinite(count) && count >= 1 && count < 1e7 ? int(count) : 0;
    if (!(std::isfinite(fps_) && fps_ > 0 && fps_ <= 1000)) fps_ = 30;  // a stream without a rate: a common one
    if (width_ < 1 || height_ < 1 || width_ > 8192 || height_ > 8192)
        throw InputError(path + ": a video of " + std::to_string(width_) + "x" + std::to_string(height_) +
                         " pixels; expected 1 to 8192 a side");
    frame(0);  // a file with no decodable frame is refused now, not at the first use
}

VideoReader::~VideoReader() = default;

void VideoReader::open() {
    video_ = mediaCodecs().openVideo(path_);
    if (!video_) throw InputError(path_ + ": not a video this build can decode (OpenCV videoio with FFmpeg)");
    next_ = 0;
}

const Image& VideoReader::frame(int index) {
    if (index < 0) index = 0;
    if (countKnown_ && frameCount_ > 0) index %= frameCount_;
    if (index == current_) return frame_;
    if (index < next_) open();  // going back: decode again from the start
    cv::Mat bgr;
    while (next_ <= index) {
        if (!video_->read(bgr)) {
            if (next_ == 0) throw InputError(path_ + ": the video has no frame this build can decode");
            // The end: now the count is known; loop to the frame asked for.
            frameCount_ = next_;
            countKnown_ = true;
            return frame(index % frameCount_);
        }
        ++next_;
    }
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb,
                 bgr.channels() == 1   ? cv::COLOR_GRAY2RGB
                 : bgr.channels() == 4 ? cv::COLOR_BGRA2RGB
                                       : cv::COLOR_BGR2RGB);
    Image img(rgb.cols, rgb.rows, 3, Image::Uninitialized{});
    const double scale = rgb.depth() == CV_16U ? 1.0 / 65535.0 : 1.0 / 255.0;
    cv::Mat floats(rgb.rows, rgb.cols, CV_32FC3, img.data().data());
    rgb.convertTo(floats, CV_32FC3, scale);
    frame_ = std::move(img);
    current_ = index;
    return frame_;
}

const Image& VideoReader::frameAt(double seconds, bool loop) {
    const double position = std::max(0.0, seconds) * fps_ + 1e-6;  // a frame's own time reads that frame
    int index = position < 1e9 ? int(std::floor(position)) : 0;
    if (!loop && frameCount_ > 0) index = std::min(index, frameCount_ - 1);  // a known count is counted too
    return frame(index);
}

}  // namespace stochtex
