#pragma once
// A recording of the workbench's picture (F3, a script's "record"): one video
// (FrameSequenceWriter: MP4, WebM, WebP, GIF or PNG frames) of one size. A
// program's frame is one frame of its own time (iTimeDelta = 1/fps), so its
// video has one frame per program frame (a paused program adds none) and
// plays at the program's speed. A pattern has no clock: its pictures go on
// the wall clock (WallClockFrames), each held until the next comes and
// written once for every frame time that fell while it was on screen, so the
// video plays what the person saw, at their pace.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "stochtex/image/image.h"
#include "stochtex/report/frame_sequence.h"

namespace stochtex {

class WorkbenchRecorder {
public:
    WorkbenchRecorder();
    ~WorkbenchRecorder();
    // Stops a recording under way (its file written), then opens `path` for
    // width × height pictures at `fps` (InputError as FrameSequenceWriter words it).
    void start(const std::string& path, int width, int height, double fps);
    bool recording() const { return writer_ != nullptr; }
    // A program's picture: written when `programFrame` is one not written yet.
    // A pattern's picture, shown `seconds` after any fixed origin.
    // Either returns false and stops (the file written) when the picture's
    // size is not the recording's: a video keeps one size.
    bool addProgramFrame(const Image& picture, long long programFrame);
    bool addPicture(const Image& picture, double seconds);
    // Writes the held picture (one frame) and closes the file; the name
    // written (the frames' pattern for PNG frames), "" when none was recording.
    std::string stop();
    long long framesWritten() const { return written_; }
    // What the last recording stopped wrote (its file, or its frames' pattern).
    const std::string& written() const { return writtenFile_; }

private:
    bool sizeMatches(const Image& picture);
    std::unique_ptr<FrameSequenceWriter> writer_;
    std::string path_, writtenFile_;
    std::array<int, 2> size_{0, 0};
    std::optional<WallClockFrames> clock_;
    std::optional<double> firstSeconds_;  // a pattern's first picture's time
    Image held_;                          // a pattern's last picture, written when the next comes
    long long lastProgramFrame_ = -1;
    long long written_ = 0;
};

}  // namespace stochtex
