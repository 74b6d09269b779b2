// libstochtex_media.so: the codecs of media_codecs.h behind its one exported
// function. Built from this folder only, with no stochtex library linked in.
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "stochtex/image/media/video_file_encoder.h"
#include "stochtex/image/media_codecs.h"

namespace stochtex::media {
namespace {

class OpenCvVideo final : public VideoDecoder {
public:
    bool open(const std::string& path) { return capture_.open(path, cv::CAP_FFMPEG) && capture_.isOpened(); }
    double width() const override { return capture_.get(cv::CAP_PROP_FRAME_WIDTH); }
    double height() const override { return capture_.get(cv::CAP_PROP_FRAME_HEIGHT); }
    double fps() const override { return capture_.get(cv::CAP_PROP_FPS); }
    double frameCount() const override { return capture_.get(cv::CAP_PROP_FRAME_COUNT); }
    bool read(cv::Mat& frame) override { return capture_.read(frame) && !frame.empty(); }

private:
    cv::VideoCapture capture_;
};

class Codecs final : public MediaCodecs {
public:
    void decodeImage(const std::vector<unsigned char>& bytes, cv::Mat& out) const override {
        out = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
    }
    void readImageFile(const std::string& path, cv::Mat& out) const override {
        out = cv::imread(path, cv::IMREAD_UNCHANGED);
    }
    bool encodeImage(const std::string& extension, const cv::Mat& image, const std::vector<int>& params,
                     std::vector<unsigned char>& out) const override {
        return cv::imencode(extension, image, out, params);
    }
    std::unique_ptr<VideoDecoder> openVideo(const std::string& path) const override {
        auto video = std::make_unique<OpenCvVideo>();
        if (!video->open(path)) return nullptr;
        return video;
    }
    bool hasVideoEncoder(VideoCodec codec) const override { return hasFfmpegEncoder(codec); }
    std::unique_ptr<VideoFileEncoder> openVideoEncoder(const std::string& path, VideoCodec codec, int width, int height,
                                                       double fps, const std::string& name) const override {
        return openFfmpegEncoder(path, codec, width, height, fps, name);
    }
};

}  // namespace
}  // namespace stochtex::media

extern "C" const stochtex::MediaCodecs* stochtex_media_codecs(int version) {
    if (version != stochtex::kMediaCodecsVersion) return nullptr;
    static const stochtex::media::Codecs codecs;
    return &codecs;
}
