#include "stochtex/workbench/analysis_runner.h"

#include <chrono>

namespace stochtex {

LiveAnalysisRunner::~LiveAnalysisRunner() {
    if (job_.valid()) job_.wait();  // the thread reads nothing of ours, but ends before we do
}

void LiveAnalysisRunner::queue(LiveAnalysisKind kind, const Image& frame) {
    Image previous;
    if (kind != LiveAnalysisKind::Spectrum) {
        if (previous_.width() != frame.width() || previous_.height() != frame.height()) previous_ = frame;
        previous = previous_;
        previous_ = frame;
    }
    queued_ = Request{kind, frame, std::move(previous)};
}

void LiveAnalysisRunner::start() {
    if (job_.valid() || !queued_) return;
    Request request = std::move(*queued_);
    queued_.reset();
    running_ = request.kind;
    job_ = std::async(std::launch::async, [request = std::move(request)] {
        switch (request.kind) {
            case LiveAnalysisKind::Spectrum: return liveSpectrum(request.frame);
            case LiveAnalysisKind::Flow: return liveFlow(request.previous, request.frame);
            default: return liveFlicker(request.previous, request.frame);
        }
    });
}

std::optional<LiveAnalysisResult> LiveAnalysisRunner::finish(LiveAnalysisKind shown) {
    const LiveAnalysisResult r = job_.get();  // rethrows the analysis's error
    if (running_ != shown) return std::nullopt;
    return r;
}

std::optional<LiveAnalysisResult> LiveAnalysisRunner::collect(LiveAnalysisKind shown, bool wait) {
    std::optional<LiveAnalysisResult> result;
    if (job_.valid() && (wait || job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready))
        result = finish(shown);
    start();
    if (wait && job_.valid())
        if (auto r = finish(shown)) result = std::move(r);
    return result;
}

LiveCorrelation& LiveAnalysisRunner::correlation(int width, int height, int x, int y, bool restart) {
    if (!correlation_ || restart || correlation_->width() != width || correlation_->height() != height ||
        correlation_->pointX() != x || correlation_->pointY() != y)
        correlation_ = std::make_unique<LiveCorrelation>(width, height, x, y);
    return *correlation_;
}

}  // namespace stochtex
