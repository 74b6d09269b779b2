#pragma once
// A frame sequence on disk, by the output path's extension (sequenceFormat):
// * `NAME.mp4`: an H.264 video (report/video_encoder.h: FFmpeg, libx264), what
//   browsers, repository previews and paper pages play;
// * `NAME.webm`: a VP9 video (libvpx), the same for a WebM;
// * `NAME.webp`: an animated WebP at full size (libwebp);
// * `NAME.gif`: an animated GIF (giflib; 256 colours a frame);
// * a path without extension, or ending in '/': a folder of frame_NNNN.png,
//   plus `<video name>` when asked for and an encoder is available.
// Any other extension is refused. Single files are written to a temporary
// file and moved into place by finish(). Beside every MP4 or WebM goes its
// animated preview for HTML pages, the same name ending in .webp
// (report/animated_preview.h).
// Every frame is checked and encoded as it comes (an animated WebP keeps its
// compressed frames until finish()).
#include <memory>
#include <string>
#include <vector>

#include "stochtex/image/colour_space.h"
#include "stochtex/image/image.h"

namespace stochtex {

enum class SequenceFormat { Folder, Mp4, WebM, AnimatedWebp, Gif };
// The format a path asks for (extension in any case). InputError naming the
// path for an extension that is none of the above.
SequenceFormat sequenceFormat(const std::string& path);
// For --help: the forms of a frame-sequence output and their codecs.
inline constexpr const char* kSequenceOutputHelp =
    "a folder of PNG frames (no extension, or ending in /), NAME.mp4 (H.264), NAME.webm (VP9), NAME.webp (animated "
    "WebP) or NAME.gif (animated GIF, 256 colours a frame)";
// True when the path names one file of frames (.mp4, .webm, .webp, .gif);
// false for a folder. InputError for another extension, as sequenceFormat.
bool isVideoPath(const std::string& path);

class FrameSequenceWriter {
public:
    // output: a file path (sequenceFormat) or a folder (created if missing).
    // videoName: the video beside the frames in folder mode, NAME.mp4 or
    // NAME.webm ("" for PNG frames only). Throws InputError when a file is
    // asked for and cannot be opened. transfer: of
    // the frames' 8-bit codes (PNG and video), as WriteOptions::transfer:
    // Srgb for colour renders, Linear for data such as zoom-texture values.
    FrameSequenceWriter(const std::string& output, int width, int height, double fps, const std::string& videoName,
                        Transfer transfer = Transfer::Srgb);
    ~FrameSequenceWriter();
    void write(const Image& frame);  // 1 (gray) or 3 (RGB) channels, [0, 1], width × height
    // Closes the file (and an MP4's or WebM's preview) and moves it into
    // place; returns its path, or "" when none was written.
    std::string finish();
    // The animated preview's path ("" without a video).
    const std::string& previewPath() const { return previewPath_; }

private:
    struct Video;
    std::string dir_;  // "" in single-file mode
    int count_ = 0;
    Transfer transfer_;
    std::unique_ptr<Video> video_;  // the file's encoder (none: PNG frames only)
    std::string previewPath_;
};

// A real-time recording's timeline: video frame k shows what was on screen
// at k / fps. Each picture shown is held until the next one comes; then the
// frames whose times fell while it was on screen are written with it (none
// when the pictures came faster than fps, several when slower), so the
// video plays what was seen at the pace it was seen. A gap longer than
// `maxGapSeconds` (a stall) counts as that long, and later frames keep their
// spacing.
class WallClockFrames {
public:
    // fps in (0, 1000], maxGapSeconds in (0, 3600] (InputError naming them).
    explicit WallClockFrames(double fps, double maxGapSeconds = 5.0);
    // A new picture is shown `seconds` after the first one: how many copies
    // of the picture held until now to write (0 or more; 0 for the first).
    int framesBefore(double seconds);
    long long written() const { return written_; }

private:
    double fps_, maxGap_;
    double cut_ = 0;  // seconds of stalls not recorded
    long long written_ = 0;
};

// Several sequences rendered side by side (one per filter of a study), each
// written as it comes into one folder: sequence i as `<names[i]>.mp4` with
// its preview (`video`) and as `<names[i]>-NNN.png` for frame NNN
// (`frames`). The videos are opened at once, so a folder or encoder that
// cannot be written is reported before any work.
class FrameSequenceSet {
public:
    struct Options {
        bool video = false;
        bool frames = false;
        double fps = 30;
        Transfer transfer = Transfer::Srgb;  // of the 8-bit codes, as FrameSequenceWriter's
    };
    FrameSequenceSet(const std::string& dir, const std::vector<std::string>& names, int width, int height,
                     const Options& options);
    ~FrameSequenceSet();
    // False when neither videos nor frames are written (write does nothing).
    bool writes() const { return options_.video || options_.frames; }
    void write(size_t sequence, int frame, const Image& image);
    // Closes the videos (FrameSequenceWriter::finish); their paths, in the order of names.
    std::vector<std::string> finish();

private:
    std::string dir_;
    std::vector<std::string> names_;
    Options options_;
    std::vector<std::unique_ptr<FrameSequenceWriter>> videos_;
};

}  // namespace stochtex
