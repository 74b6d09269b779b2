#pragma once
// The codecs that live in a plugin: OpenCV's imgcodecs (OpenEXR, JPEG, TIFF)
// and videoio, and FFmpeg's encoders. Linked into the binary they brought
// in ~190 of its ~260 shared libraries, whose loading and symbol relocation
// was most of every command's start-up (0.2–0.3 s before any work, also for
// `--version` or a PNG render). They are built into libstochtex_media.so,
// beside the binary (or the shared object) that uses them, and loaded the
// first time something reads or writes such a file: mediaCodecs().
//
// The interface speaks OpenCV and std types only, so the plugin holds none
// of stochtex's libraries; it reports bad input as InputError (header-only:
// the host catches it as its own, libstdc++ matching types by name).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cv {
class Mat;
}

namespace stochtex {

// The encoders of the videos a study writes (report/video_encoder.h).
enum class VideoCodec { H264, Vp9 };

// A video file's frames in order (OpenCV videoio through FFmpeg).
class VideoDecoder {
public:
    virtual ~VideoDecoder() = default;
    // As the container states them: NaN or 0 where it does not.
    virtual double width() const = 0;
    virtual double height() const = 0;
    virtual double fps() const = 0;
    virtual double frameCount() const = 0;
    // The next frame as OpenCV decodes it (BGR or BGRA or gray, 8 or 16
    // bits); false at the end or where it cannot be decoded.
    virtual bool read(cv::Mat& frame) = 0;
};

// An H.264/MP4 or VP9/WebM file being written (report/video_encoder.h says how).
class VideoFileEncoder {
public:
    virtual ~VideoFileEncoder() = default;
    // One frame of the encoder's even size (paddedSide of the width and
    // height), 8-bit sRGB codes, RGB interleaved, rows top first.
    virtual void add(const uint8_t* rgb) = 0;
    // Flushes the encoder, writes the index and closes the file.
    virtual void finish() = 0;
};

// 4:2:0 needs even sides: an odd one is padded by one pixel.
constexpr int paddedSide(int side) { return (side + 1) & ~1; }

class MediaCodecs {
public:
    virtual ~MediaCodecs() = default;
    // OpenCV's image decoders on a file's bytes (JPEG) or on a file (OpenEXR,
    // which OpenCV decodes only from a file), as cv::imdecode / cv::imread
    // with IMREAD_UNCHANGED: an empty Mat where they fail. cv::Exception may
    // escape.
    virtual void decodeImage(const std::vector<unsigned char>& bytes, cv::Mat& out) const = 0;
    virtual void readImageFile(const std::string& path, cv::Mat& out) const = 0;
    // cv::imencode: false where it fails; cv::Exception may escape.
    virtual bool encodeImage(const std::string& extension, const cv::Mat& image, const std::vector<int>& params,
                             std::vector<unsigned char>& out) const = 0;
    // Null where OpenCV cannot open the file as a video.
    virtual std::unique_ptr<VideoDecoder> openVideo(const std::string& path) const = 0;
    virtual bool hasVideoEncoder(VideoCodec codec) const = 0;
    // InputError naming `name` where the file cannot be opened or the
    // encoder is missing (report/video_encoder.h).
    virtual std::unique_ptr<VideoFileEncoder> openVideoEncoder(const std::string& path, VideoCodec codec, int width,
                                                               int height, double fps,
                                                               const std::string& name) const = 0;
};

// Changes with the interface above: a plugin built from another version of
// it is refused rather than called.
constexpr int kMediaCodecsVersion = 1;
constexpr const char* kMediaPluginFile = "libstochtex_media.so";
// The plugin's one exported function: its codecs, or null when `version`
// is not the one it was built with.
using MediaPluginEntry = const MediaCodecs* (*)(int version);
constexpr const char* kMediaPluginEntry = "stochtex_media_codecs";

// The codecs, loading the plugin on the first call (thread-safe). Throws
// std::runtime_error naming the file looked for and why it failed to load
// (an installation fault, not the user's input).
const MediaCodecs& mediaCodecs();

}  // namespace stochtex
