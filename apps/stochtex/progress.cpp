#include "progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <sys/ioctl.h>
#include <unistd.h>

namespace stochtex::cli {

namespace {

bool gQuiet = false;

// Characters of a UTF-8 string (bytes that do not continue a sequence).
size_t columnsOf(const std::string& s) {
    size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
}

// The first `columns` characters of s, never cutting a UTF-8 sequence.
std::string cutToColumns(const std::string& s, size_t columns) {
    size_t n = 0;
    for (size_t i = 0; i < s.size(); ++i)
        if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 && n++ == columns) return s.substr(0, i);
    return s;
}

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int stderrColumns() {
    winsize w{};
    return ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0 ? int(w.ws_col) : 80;
}

}  // namespace

std::string formatDuration(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    if (s < 60)
        std::snprintf(text, sizeof text, "%lds", s);
    else if (s < 3600)
        std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, s % 3600 / 60);
    return text;
}

std::string formatProgressLine(const std::string& title, double fraction, double elapsed, const std::string& step,
                               int columns) {
    std::string line = title + ":";
    if (fraction >= 0) {
        const double f = std::min(fraction, 1.0);
        char percent[16];
        std::snprintf(percent, sizeof percent, " %d%%", int(std::floor(f * 100)));
        line += percent;
        if (f >= 0.01 && elapsed >= 1.0) line += "  ETA " + formatDuration(elapsed * (1 - f) / f);
    }
    if (!step.empty()) line += "  " + step;
    return cutToColumns(line, size_t(std::max(columns, 1)));
}

void setProgressQuiet(bool quiet) { gQuiet = quiet; }

bool progressShown() { return !gQuiet && isatty(STDERR_FILENO); }

ProgressLine::ProgressLine(std::string title)
    : ProgressLine(std::move(title), Settings{progressShown(), stderr, steadySeconds, stderrColumns()}) {}

ProgressLine::ProgressLine(std::string title, Settings settings)
    : title_(std::move(title)), settings_(std::move(settings)) {
    if (settings_.enabled) start_ = settings_.clock();
}

ProgressLine::~ProgressLine() { end(); }

void ProgressLine::update(double fraction, const std::string& step) {
    if (!settings_.enabled) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    fraction_ = fraction;
    if (!step.empty()) step_ = step;
    const double now = settings_.clock();
    if (now - start_ < settings_.delay || (lastDraw_ >= 0 && now - lastDraw_ < settings_.interval)) return;
    lastDraw_ = now;
    draw(formatProgressLine(title_, fraction_, now - start_, step_, settings_.columns - 1));
}

void ProgressLine::finish() {
    if (!settings_.enabled) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!onScreen_) return;
    draw(formatProgressLine(title_, 1.0, 0.0, "done in " + formatDuration(settings_.clock() - start_),
                            settings_.columns - 1));
    std::fputc('\n', settings_.out);
    onScreen_ = false;
}

void ProgressLine::end() {
    if (!settings_.enabled) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!onScreen_) return;
    std::fputc('\n', settings_.out);
    std::fflush(settings_.out);
    onScreen_ = false;
}

Progress ProgressLine::callback() {
    return [this](double fraction, const std::string& step) { update(fraction, step); };
}

void ProgressLine::draw(const std::string& line) {
    // A new line starts afresh; a redraw blanks what a longer one left.
    const size_t columns = columnsOf(line);
    const size_t blank = onScreen_ && shownColumns_ > columns ? shownColumns_ - columns : 0;
    std::fprintf(settings_.out, "\r%s%s", line.c_str(), std::string(blank, ' ').c_str());
    std::fflush(settings_.out);
    shownColumns_ = columns;
    onScreen_ = true;
}

}  // namespace stochtex::cli
