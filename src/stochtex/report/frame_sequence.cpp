#include "stochtex/report/frame_sequence.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/animated_preview.h"
#include "stochtex/report/page.h"

namespace stochtex {
namespace fs = std::filesystem;

bool isVideoPath(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".mp4";
}

struct FrameSequenceWriter::Video {
    // The encoder opens the temporary file by name; its ".mp4" ending picks the container.
    std::unique_ptr<AtomicFile> file;
    cv::VideoWriter writer;
    std::unique_ptr<AnimatedPreviewWriter> preview;
};

FrameSequenceWriter::FrameSequenceWriter(const std::string& output, int width, int height, double fps,
                                         const std::string& videoName, Transfer transfer)
    : transfer_(transfer), video_(std::make_unique<Video>()) {
    std::string videoPath;
    if (isVideoPath(output)) {
        videoPath = output;
    } else {
        dir_ = output;
        ensureFolder(dir_);
        if (!videoName.empty()) videoPath = (fs::path(dir_) / videoName).string();
    }
    if (videoPath.empty()) return;
    video_->file = std::make_unique<AtomicFile>(videoPath, ".tmp.mp4");
    ::close(video_->file->releaseDescriptor());
    // MPEG-4 part 2: FFmpeg's own encoder, present in every FFmpeg build.
    video_->writer.open(video_->file->tempPath(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps,
                        cv::Size(width, height), true);
    if (video_->writer.isOpened()) {
        previewPath_ = fs::path(videoPath).replace_extension(".webp").string();
        video_->preview = std::make_unique<AnimatedPreviewWriter>(previewPath_, width, height, fps);
        return;
    }
    if (dir_.empty()) throw InputError(output + ": cannot write MP4 (OpenCV has no FFmpeg MP4 encoder here)");
    std::fprintf(stderr, "note: no MP4 encoder available in this OpenCV build; writing PNG frames only\n");
    video_->file.reset();
}

FrameSequenceWriter::~FrameSequenceWriter() = default;

void FrameSequenceWriter::write(const Image& linearFrame) {
    // Encoded once for the PNG frame and the video alike.
    const Image frame = encodeTransfer(linearFrame, transfer_);
    if (!dir_.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", count_);
        writeImage((fs::path(dir_) / name).string(), frame, kNoTransfer);
    }
    ++count_;
    if (!video_->file) return;
    if (frame.channels() != 1 && frame.channels() != 3)
        throw std::invalid_argument("FrameSequenceWriter::write: 1- or 3-channel frames");
    // 8-bit BGR, what the encoder takes; gray frames as equal channels.
    cv::Mat m(frame.height(), frame.width(), CV_8UC3);
    for (int y = 0; y < frame.height(); ++y) {
        const float* src = frame.row(y);
        auto* dst = m.ptr<cv::Vec3b>(y);
        for (int x = 0; x < frame.width(); ++x) {
            for (int c = 0; c < 3; ++c) {
                const float v = frame.channels() == 1 ? src[x] : src[3 * x + (2 - c)];
                dst[x][c] = uchar(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f)));
            }
        }
    }
    video_->writer.write(m);
    video_->preview->add(frame);
}

std::string FrameSequenceWriter::finish() {
    if (!video_->file) return "";
    video_->writer.release();
    video_->preview->finish();
    video_->file->commit();
    return video_->file->path();
}

FrameSequenceSet::FrameSequenceSet(const std::string& dir, const std::vector<std::string>& names, int width, int height,
                                   const Options& options)
    : dir_(dir), names_(names), options_(options) {
    if (!options.video) return;
    for (const std::string& name : names)
        videos_.push_back(std::make_unique<FrameSequenceWriter>((fs::path(dir) / (name + ".mp4")).string(), width,
                                                                height, options.fps, "", options.transfer));
}

FrameSequenceSet::~FrameSequenceSet() = default;

void FrameSequenceSet::write(size_t sequence, int frame, const Image& image) {
    if (options_.video) videos_.at(sequence)->write(image);
    if (!options_.frames) return;
    char file[32];
    std::snprintf(file, sizeof file, "-%03d.png", frame);
    writeImage((fs::path(dir_) / (names_.at(sequence) + file)).string(), image, {.transfer = options_.transfer});
}

std::vector<std::string> FrameSequenceSet::finish() {
    std::vector<std::string> paths;
    for (const auto& video : videos_) paths.push_back(video->finish());
    return paths;
}

WallClockFrames::WallClockFrames(double fps, double maxGapSeconds) : fps_(fps), maxGap_(maxGapSeconds) {
    if (!(fps > 0 && fps <= 1000)) throw InputError::parameter("fps", "must be in (0, 1000], got " + formatValue(fps));
    if (!(maxGapSeconds > 0 && maxGapSeconds <= 3600))
        throw InputError::parameter("maxGapSeconds", "must be in (0, 3600], got " + formatValue(maxGapSeconds));
}

int WallClockFrames::framesBefore(double seconds) {
    // Frames k with k / fps before now showed the picture held until now.
    const double t = std::clamp(seconds - cut_, 0.0, 1e9);
    long long due = (long long)(std::ceil(t * fps_));
    const long long most = written_ + (long long)(std::ceil(maxGap_ * fps_));
    if (due > most) {
        cut_ += double(due - most) / fps_;
        due = most;
    }
    const int n = int(std::max(0LL, due - written_));
    written_ += n;
    return n;
}

}  // namespace stochtex
