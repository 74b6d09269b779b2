#include "stochtex/report/frame_sequence.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>
#include <stdexcept>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"
#include "stochtex/core/notes.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/animated_gif.h"
#include "stochtex/report/animated_preview.h"
#include "stochtex/report/page.h"
#include "stochtex/report/video_encoder.h"

namespace stochtex {
namespace fs = std::filesystem;

SequenceFormat sequenceFormat(const std::string& path) {
    if (path.empty()) throw InputError("output path is empty");
    if (path.back() == '/') return SequenceFormat::Folder;
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext.empty()) return SequenceFormat::Folder;
    if (ext == ".mp4") return SequenceFormat::Mp4;
    if (ext == ".webm") return SequenceFormat::WebM;
    if (ext == ".webp") return SequenceFormat::AnimatedWebp;
    if (ext == ".gif") return SequenceFormat::Gif;
    throw InputError(path + ": cannot write frames as \"" + ext + "\" (expected " + kSequenceOutputHelp + ")");
}

bool isVideoPath(const std::string& path) { return sequenceFormat(path) != SequenceFormat::Folder; }

// The encoder of the one file: a video (MP4, WebM) with its preview, an
// animated WebP or an animated GIF.
struct FrameSequenceWriter::Video {
    std::unique_ptr<AtomicFile> file;  // a video's, which FFmpeg opens by name (in a private folder)
    std::unique_ptr<VideoEncoder> video;
    std::unique_ptr<AnimatedPreviewWriter> preview, webp;
    std::unique_ptr<AnimatedGifWriter> gif;

    // Opens the video; false when this FFmpeg build lacks the codec's encoder.
    bool openVideo(const std::string& path, SequenceFormat format, int width, int height, double fps) {
        const VideoCodec codec = format == SequenceFormat::WebM ? VideoCodec::Vp9 : VideoCodec::H264;
        if (!hasVideoEncoder(codec)) return false;
        // FFmpeg opens the file by name (and reopens an MP4 to move its index
        // first): in a folder of its own no one can swap it for a link.
        file = std::make_unique<AtomicFile>(path, "", AtomicFile::Placement::PrivateFolder);
        ::close(file->releaseDescriptor());
        video = std::make_unique<VideoEncoder>(file->tempPath(), codec, width, height, fps, path);
        return true;
    }

    void add(const Image& codes) {
        if (webp) return webp->add(codes);
        if (gif) return gif->add(codes);
        video->add(codes);
        preview->add(codes);
    }

    std::string finish() {
        if (webp) return webp->finish();
        if (gif) return gif->finish();
        video->finish();
        preview->finish();
        file->commit();
        return file->path();
    }
};

FrameSequenceWriter::FrameSequenceWriter(const std::string& output, int width, int height, double fps,
                                         const std::string& videoName, Transfer transfer)
    : transfer_(transfer) {
    std::string path;
    SequenceFormat format = sequenceFormat(output);
    if (format != SequenceFormat::Folder) {
        path = output;
    } else {
        if (!videoName.empty()) {
            format = sequenceFormat(videoName);
            if (format != SequenceFormat::Mp4 && format != SequenceFormat::WebM)
                throw std::invalid_argument("FrameSequenceWriter: the video beside frames is an .mp4 or a .webm");
            path = (fs::path(output) / videoName).string();
        }
        dir_ = output;
        ensureFolder(dir_);
    }
    if (path.empty()) return;
    auto video = std::make_unique<Video>();
    switch (format) {
        case SequenceFormat::AnimatedWebp:
            // Full size, near-transparent quality: the clip itself, not a preview.
            video->webp = std::make_unique<AnimatedPreviewWriter>(path, width, height, fps, std::max(width, height), 90.0f);
            break;
        case SequenceFormat::Gif:
            video->gif = std::make_unique<AnimatedGifWriter>(path, width, height, fps);
            break;
        case SequenceFormat::Mp4:
        case SequenceFormat::WebM:
            if (!video->openVideo(path, format, width, height, fps)) {
                if (dir_.empty()) throw InputError(output + ": cannot write this video (this FFmpeg build lacks its encoder)");
                note("no " + std::string(format == SequenceFormat::WebM ? "VP9" : "H.264") +
                     " encoder in this FFmpeg build; writing PNG frames only");
                return;
            }
            previewPath_ = fs::path(path).replace_extension(".webp").string();
            video->preview = std::make_unique<AnimatedPreviewWriter>(previewPath_, width, height, fps);
            break;
        case SequenceFormat::Folder:
            break;
    }
    video_ = std::move(video);
}

FrameSequenceWriter::~FrameSequenceWriter() = default;

void FrameSequenceWriter::write(const Image& linearFrame) {
    // Encoded once for the PNG frame and the file alike.
    const Image frame = encodeTransfer(linearFrame, transfer_);
    if (!dir_.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", count_);
        writeImage((fs::path(dir_) / name).string(), frame, kNoTransfer);
    }
    ++count_;
    if (video_) video_->add(frame);
}

std::string FrameSequenceWriter::finish() {
    if (!video_) return "";
    const std::string path = video_->finish();
    video_.reset();
    return path;
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
