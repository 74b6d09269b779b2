#pragma once
// The workbench's live analyses, scheduled (issue 31 item 1): the spectrum,
// flow and flicker of the frames shown run beside the window, since a flow of
// a large picture takes longer than a frame. The frame read when the picture
// changes (and, for flow and flicker, the frame before it) is queued, the
// newest replacing an older one still waiting, and the last analysis
// finished is shown; a frame that is captured waits for the analysis of
// itself. The correlation accumulates samples over frames (a program's) or
// instances (a pattern's) at a picked point. No GL: the window reads the
// frames and shows the results.
#include <future>
#include <memory>
#include <optional>

#include "stochtex/image/image.h"
#include "stochtex/workbench/live_analysis.h"

namespace stochtex {

class LiveAnalysisRunner {
public:
    ~LiveAnalysisRunner();
    // A new frame of the picture for the spectrum, flow or flicker: queued,
    // replacing one still waiting. Flow and flicker pair it with the frame
    // queued before it (the same frame after a change of size or a restart).
    void queue(LiveAnalysisKind kind, const Image& frame);
    // Forgets the frame before (a new view, analysis or mode).
    void restart() { previous_ = {}; }
    // Starts the queued analysis when none runs, and returns one that
    // finished if it is of `shown` (one of an analysis since switched away
    // from is dropped); `wait`: waits for the running one and the queued one.
    // Rethrows the analysis's error.
    std::optional<LiveAnalysisResult> collect(LiveAnalysisKind shown, bool wait);
    bool running() const { return job_.valid(); }

    // The correlation's samples at (x, y) of width × height pictures,
    // started again when `restart` or any of these changed.
    LiveCorrelation& correlation(int width, int height, int x, int y, bool restart);
    int correlationSamples() const { return correlation_ ? correlation_->count() : 0; }

private:
    struct Request {
        LiveAnalysisKind kind;
        Image frame, previous;
    };
    void start();
    std::optional<LiveAnalysisResult> finish(LiveAnalysisKind shown);
    std::future<LiveAnalysisResult> job_;
    LiveAnalysisKind running_ = LiveAnalysisKind::Spectrum;
    std::optional<Request> queued_;
    Image previous_;
    std::unique_ptr<LiveCorrelation> correlation_;
};

}  // namespace stochtex
