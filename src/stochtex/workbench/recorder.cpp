#include "stochtex/workbench/recorder.h"

namespace stochtex {

WorkbenchRecorder::WorkbenchRecorder() = default;
WorkbenchRecorder::~WorkbenchRecorder() = default;

void WorkbenchRecorder::start(const std::string& path, int width, int height, double fps) {
    stop();
    writer_ = std::make_unique<FrameSequenceWriter>(path, width, height, fps, "", Transfer::Linear);
    path_ = path;
    size_ = {width, height};
    clock_.emplace(fps);
    firstSeconds_.reset();
    held_ = {};
    lastProgramFrame_ = -1;
    written_ = 0;
}

bool WorkbenchRecorder::sizeMatches(const Image& picture) {
    if (picture.width() == size_[0] && picture.height() == size_[1]) return true;
    stop();
    return false;
}

bool WorkbenchRecorder::addProgramFrame(const Image& picture, long long programFrame) {
    if (!writer_) return true;
    if (!sizeMatches(picture)) return false;
    if (programFrame != lastProgramFrame_) writer_->write(picture), ++written_;
    lastProgramFrame_ = programFrame;
    return true;
}

bool WorkbenchRecorder::addPicture(const Image& picture, double seconds) {
    if (!writer_) return true;
    if (!sizeMatches(picture)) return false;
    // The clock starts at the first picture (the first frame may take a build).
    if (!firstSeconds_) {
        firstSeconds_ = seconds;
        held_ = picture;
        return true;
    }
    const int frames = clock_->framesBefore(seconds - *firstSeconds_);
    for (int k = 0; k < frames; ++k) writer_->write(held_), ++written_;
    held_ = picture;
    return true;
}

std::string WorkbenchRecorder::stop() {
    if (!writer_) return "";
    const std::unique_ptr<FrameSequenceWriter> w = std::move(writer_);
    if (!held_.empty()) w->write(held_), ++written_;  // the last picture, one frame
    held_ = {};
    const std::string written = w->finish();
    writtenFile_ = written.empty() ? path_ : written;
    return writtenFile_;
}

}  // namespace stochtex
