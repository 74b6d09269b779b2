#pragma once
// The progress line of a long command on a terminal:
//   render: 42%  ETA 12s  reference: footprint 8²
// redrawn in place (\r) on stderr, at most every `interval` seconds and only
// once the command has run `delay` seconds (a quick command draws nothing).
// Nothing at all when stderr is not a terminal or with --quiet. The line is
// ended (newline) before anything else is printed: by finish() before the
// report, or by the destructor while an error unwinds, so an error message
// never shares a line with it.
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>

#include "stochtex/core/progress.h"

namespace stochtex::cli {

// A duration for an ETA, to the second: "7s", "1m05s", "2h03m".
std::string formatDuration(double seconds);

// One progress line without the \r: "title: P%", "  ETA D" once the
// estimate elapsed·(1 − f)/f means something (f ≥ 1% and elapsed ≥ 1 s),
// then the step; cut to `columns` characters (UTF-8 aware). fraction < 0:
// not known (no percentage or ETA).
std::string formatProgressLine(const std::string& title, double fraction, double elapsed, const std::string& step,
                               int columns);

// --quiet (main sets it): no progress lines.
void setProgressQuiet(bool quiet);
// Whether progress lines are drawn: stderr is a terminal and no --quiet.
bool progressShown();

class ProgressLine {
public:
    using Clock = std::function<double()>;  // monotonic seconds
    struct Settings {
        bool enabled = false;
        std::FILE* out = stderr;
        Clock clock;
        int columns = 80;       // the terminal's width; the line stays one character shorter
        double interval = 0.1;  // s between redraws
        double delay = 0.5;     // s before the first draw
    };
    // For a command: enabled by progressShown(), the steady clock, stderr's width.
    explicit ProgressLine(std::string title);
    ProgressLine(std::string title, Settings settings);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // fraction in [0, 1] (< 0: unknown); an empty step keeps the last one.
    // Thread-safe.
    void update(double fraction, const std::string& step = "");
    // Success: a drawn line shows 100% and the time taken, then ends.
    void finish();
    // Ends a drawn line with a newline (nothing otherwise).
    void end();
    // A library callback drawing on this line (valid while it lives).
    Progress callback();

private:
    void draw(const std::string& line);
    std::string title_;
    Settings settings_;
    std::mutex mutex_;
    double start_ = 0, lastDraw_ = -1;
    double fraction_ = -1;
    std::string step_;
    size_t shownColumns_ = 0;  // of the line on screen, to blank a longer one
    bool onScreen_ = false;
};

}  // namespace stochtex::cli
