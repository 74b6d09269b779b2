// The plugin's H.264/VP9 writer (media_codecs.h): FFmpeg's libraries
// directly, for the choices report/video_encoder.h describes.
#include "stochtex/image/media/video_file_encoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "stochtex/core/error.h"

namespace stochtex::media {

namespace {

const char* encoderName(VideoCodec codec) { return codec == VideoCodec::H264 ? "libx264" : "libvpx-vp9"; }

std::string avError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

// FFmpeg's log stays out of the user's terminal: the message of a failure
// says what failed, with FFmpeg's last error line (a missing encoder printed
// three lines of log before it). STOCHTEX_FFMPEG_LOG=1 shows the log as
// FFmpeg prints it, for a bug report.
std::mutex gLogMutex;
std::string gLastLogError;

void keepLastError(void* context, int level, const char* format, va_list args) {
    if (level > AV_LOG_ERROR) return;
    char line[1024];
    int printPrefix = 1;
    av_log_format_line2(context, level, format, args, line, sizeof line, &printPrefix);
    std::string text = line;
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    const std::lock_guard<std::mutex> lock(gLogMutex);
    gLastLogError = text;
}

void quietFfmpegLog() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (std::getenv("STOCHTEX_FFMPEG_LOG")) return av_log_set_level(AV_LOG_INFO);
        av_log_set_callback(keepLastError);
    });
}

std::string lastFfmpegError() {
    const std::lock_guard<std::mutex> lock(gLogMutex);
    return gLastLogError;
}

}  // namespace

bool hasFfmpegEncoder(VideoCodec codec) {
    quietFfmpegLog();
    return avcodec_find_encoder_by_name(encoderName(codec)) != nullptr;
}

namespace {

struct EncoderState {
    std::string name;  // what errors name
    int width = 0, height = 0;
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scale = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    int64_t next = 0;  // the next frame's pts
    bool finished = false;

    // An unfinished file is discarded (its AtomicFile removes it), so no
    // trailer is written here: after a failed one FFmpeg's muxer state is
    // gone, and a second av_write_trailer crashed.
    ~EncoderState() {
        if (format && format->pb) avio_closep(&format->pb);
        avformat_free_context(format);
        avcodec_free_context(&codec);
        sws_freeContext(scale);
        av_frame_free(&frame);
        av_packet_free(&packet);
    }

    [[noreturn]] void fail(const std::string& what, int code) const {
        const std::string log = lastFfmpegError();
        throw InputError(name + ": cannot write the video (" + what + (code ? ": " + avError(code) : "") +
                         (log.empty() ? "" : "; FFmpeg: " + log) + ")");
    }

    // Sends a frame (null: end of stream) and writes every packet it gives back.
    void send(const AVFrame* f) {
        int status = avcodec_send_frame(codec, f);
        if (status < 0) fail("encoding", status);
        while ((status = avcodec_receive_packet(codec, packet)) >= 0) {
            // Every frame lasts one frame: without it the muxer gives the last
            // one no duration, and players (OpenCV's reader) drop it.
            packet->duration = 1;
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            if (const int w = av_interleaved_write_frame(format, packet); w < 0) fail("writing", w);
        }
        if (status != AVERROR(EAGAIN) && status != AVERROR_EOF) fail("encoding", status);
    }
};

class FfmpegEncoder final : public VideoFileEncoder {
public:
    FfmpegEncoder(const std::string& path, VideoCodec codec, int width, int height, double fps,
                  const std::string& name);
    void add(const uint8_t* rgb) override;
    void finish() override;

private:
    EncoderState s_;
};

FfmpegEncoder::FfmpegEncoder(const std::string& path, VideoCodec codecKind, int width, int height, double fps,
                             const std::string& name) {
    EncoderState& s = s_;
    quietFfmpegLog();
    {
        const std::lock_guard<std::mutex> lock(gLogMutex);
        gLastLogError.clear();  // this encoder's errors only
    }
    s.name = name.empty() ? path : name;
    s.width = width;
    s.height = height;
    if (width < 1 || height < 1 || width > 16384 || height > 16384) s.fail("frames of 1 to 16384 pixels a side", 0);
    if (!(fps > 0 && fps <= 1000)) s.fail("fps must be in (0, 1000]", 0);
    const AVCodec* encoder = avcodec_find_encoder_by_name(encoderName(codecKind));
    if (!encoder) s.fail(std::string("this FFmpeg build has no ") + encoderName(codecKind) + " encoder", 0);
    const char* container = codecKind == VideoCodec::H264 ? "mp4" : "webm";
    if (const int e = avformat_alloc_output_context2(&s.format, nullptr, container, path.c_str()); e < 0)
        s.fail("container", e);
    // No metadata that changes from run to run (the muxer's version string stays).
    s.format->flags |= AVFMT_FLAG_BITEXACT;

    s.codec = avcodec_alloc_context3(encoder);
    if (!s.codec) throw std::bad_alloc();
    // 4:2:0 needs even sides: odd ones are padded by one pixel.
    s.codec->width = paddedSide(width);
    s.codec->height = paddedSide(height);
    s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    // A rational frame rate: 30000/1001 and 23.976 stay exact at 1/1000 s.
    const AVRational rate = av_d2q(fps, 100000);
    s.codec->framerate = rate;
    s.codec->time_base = av_inv_q(rate);
    s.codec->gop_size = 250;
    s.codec->thread_count = 1;  // reproducible: the same frames give the same file
    s.codec->color_range = AVCOL_RANGE_MPEG;
    s.codec->colorspace = AVCOL_SPC_BT709;
    s.codec->color_primaries = AVCOL_PRI_BT709;
    s.codec->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB codes
    if (s.format->oformat->flags & AVFMT_GLOBALHEADER) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = nullptr;
    if (codecKind == VideoCodec::H264) {
        av_dict_set(&options, "crf", "18", 0);  // visually near-lossless
        av_dict_set(&options, "preset", "medium", 0);
        // x264's macroblock tree made one in ~8 encodings of the same
        // frames differ, even on one thread (measured: 30 of 30 identical
        // without it at 32–96 pixels); its gain is a few % of bit rate.
        av_dict_set(&options, "x264-params", "mbtree=0", 0);
    } else {
        av_dict_set(&options, "crf", "30", 0);
        av_dict_set(&options, "b", "0", 0);  // constant quality
        av_dict_set(&options, "row-mt", "0", 0);
    }
    const int opened = avcodec_open2(s.codec, encoder, &options);
    av_dict_free(&options);
    if (opened < 0) s.fail(std::string("opening ") + encoderName(codecKind), opened);

    s.stream = avformat_new_stream(s.format, nullptr);
    if (!s.stream) throw std::bad_alloc();
    s.stream->time_base = s.codec->time_base;
    if (const int e = avcodec_parameters_from_context(s.stream->codecpar, s.codec); e < 0) s.fail("stream", e);
    if (const int e = avio_open(&s.format->pb, path.c_str(), AVIO_FLAG_WRITE); e < 0) s.fail("opening the file", e);
    AVDictionary* muxer = nullptr;
    if (codecKind == VideoCodec::H264) av_dict_set(&muxer, "movflags", "+faststart", 0);
    const int header = avformat_write_header(s.format, &muxer);
    av_dict_free(&muxer);
    if (header < 0) s.fail("header", header);

    s.scale =
        sws_getContext(s.codec->width, s.codec->height, AV_PIX_FMT_RGB24, s.codec->width, s.codec->height,
                       AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
    if (!s.scale) s.fail("colour conversion", 0);
    // RGB codes → BT.709 limited-range YUV, as the stream says.
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(s.scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    s.frame = av_frame_alloc();
    s.packet = av_packet_alloc();
    if (!s.frame || !s.packet) throw std::bad_alloc();
    s.frame->format = s.codec->pix_fmt;
    s.frame->width = s.codec->width;
    s.frame->height = s.codec->height;
    if (const int e = av_frame_get_buffer(s.frame, 0); e < 0) s.fail("frame", e);
}

void FfmpegEncoder::add(const uint8_t* rgb) {
    EncoderState& s = s_;
    if (s.finished) throw std::logic_error("VideoFileEncoder::add after finish");
    const int w = s.codec->width, h = s.codec->height;
    if (const int e = av_frame_make_writable(s.frame); e < 0) s.fail("frame", e);
    const uint8_t* source[1] = {rgb};
    const int stride[1] = {3 * w};
    sws_scale(s.scale, source, stride, 0, h, s.frame->data, s.frame->linesize);
    s.frame->pts = s.next++;
    s.send(s.frame);
}

void FfmpegEncoder::finish() {
    EncoderState& s = s_;
    if (s.finished) return;
    s.send(nullptr);
    s.finished = true;  // whatever happens next, never a second trailer
    if (const int e = av_write_trailer(s.format); e < 0) s.fail("closing", e);
    // Every write checked: avio buffers them, keeps the first error in
    // pb->error, and this FFmpeg's avio_close does not return it (a full disk
    // left an MP4 without its index and exit 0).
    avio_flush(s.format->pb);
    if (s.format->pb->error < 0) s.fail("writing", s.format->pb->error);
    if (const int e = avio_closep(&s.format->pb); e < 0) s.fail("closing", e);
}

}  // namespace

std::unique_ptr<VideoFileEncoder> openFfmpegEncoder(const std::string& path, VideoCodec codec, int width, int height,
                                                    double fps, const std::string& name) {
    return std::make_unique<FfmpegEncoder>(path, codec, width, height, fps, name);
}

}  // namespace stochtex::media
