// The CLI's progress line (apps/stochtex/progress.h): its text, and when it
// is drawn, with an injected clock and a memory stream for stderr.
#include "progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace stochtex::cli {
namespace {

TEST(ProgressText, DurationsReadToTheSecond) {
    EXPECT_EQ(formatDuration(0), "0s");
    EXPECT_EQ(formatDuration(7.4), "7s");
    EXPECT_EQ(formatDuration(59.6), "1m00s");  // rounded to the second, then split
    EXPECT_EQ(formatDuration(65), "1m05s");
    EXPECT_EQ(formatDuration(7380), "2h03m");
    EXPECT_EQ(formatDuration(-3), "0s");  // never a negative estimate
}

TEST(ProgressText, EtaIsElapsedTimesTheRemainingOverTheDoneFraction) {
    // 25% done in 10 s: 30 s to go.
    EXPECT_EQ(formatProgressLine("render", 0.25, 10.0, "rendering", 80), "render: 25%  ETA 30s  rendering");
    // 60% in 90 s: 60 s to go; the percentage is floored (never 100% early).
    EXPECT_EQ(formatProgressLine("zoom", 0.6, 90.0, "", 80), "zoom: 60%  ETA 1m00s");
    EXPECT_EQ(formatProgressLine("zoom", 0.999, 90.0, "", 80), "zoom: 99%  ETA 0s");
}

TEST(ProgressText, NoEtaBeforeItMeansSomething) {
    EXPECT_EQ(formatProgressLine("a", 0.005, 100.0, "", 80), "a: 0%");               // under 1% done
    EXPECT_EQ(formatProgressLine("a", 0.5, 0.5, "", 80), "a: 50%");                  // under 1 s elapsed
    EXPECT_EQ(formatProgressLine("a", -1.0, 50.0, "building", 80), "a:  building");  // fraction unknown
}

TEST(ProgressText, CutToTheTerminalWidthWithoutSplittingACharacter) {
    // "a: 50%  fp 8²x" is 14 characters, 15 bytes (² is two).
    EXPECT_EQ(formatProgressLine("a", 0.5, 0.0, "fp 8²x", 13), "a: 50%  fp 8²");
    EXPECT_EQ(formatProgressLine("a", 0.5, 0.0, "fp 8²x", 12), "a: 50%  fp 8");
    EXPECT_EQ(formatProgressLine("a", 0.5, 0.0, "fp 8²x", 80), "a: 50%  fp 8²x");
}

// A ProgressLine drawing into memory, its clock set by the test.
struct Fixture {
    char* buffer = nullptr;
    size_t size = 0;
    std::FILE* out = open_memstream(&buffer, &size);
    double now = 0;
    ProgressLine::Settings settings(bool enabled = true) {
        ProgressLine::Settings s;
        s.enabled = enabled;
        s.out = out;
        s.clock = [this] { return now; };
        s.columns = 80;
        s.interval = 0.1;
        s.delay = 0.5;
        return s;
    }
    std::string text() {
        std::fflush(out);
        return std::string(buffer, size);
    }
    ~Fixture() {
        std::fclose(out);
        std::free(buffer);
    }
};

TEST(ProgressLine, DrawsAfterTheDelayAtMostOncePerInterval) {
    Fixture f;
    ProgressLine line("t", f.settings());
    line.update(0.1, "a");
    EXPECT_EQ(f.text(), "");  // t = 0 < 0.5 s: a quick command draws nothing
    f.now = 0.6;
    line.update(0.2);  // the step named before the first draw is kept
    EXPECT_EQ(f.text(), "\rt: 20%  a");
    f.now = 0.65;
    line.update(0.3, "b");
    EXPECT_EQ(f.text(), "\rt: 20%  a");  // 0.05 s after the last draw: rate-limited
    f.now = 0.75;
    line.update(0.4);
    EXPECT_EQ(f.text(), "\rt: 20%  a\rt: 40%  b");
    f.now = 2.0;
    line.update(0.5, "c");  // 2 s for half: 2 s to go
    EXPECT_EQ(f.text(), "\rt: 20%  a\rt: 40%  b\rt: 50%  ETA 2s  c");
}

TEST(ProgressLine, BlanksWhatALongerLineLeft) {
    Fixture f;
    ProgressLine line("t", f.settings());
    f.now = 1.0;
    line.update(-1, "long step");
    f.now = 2.0;
    line.update(-1, "short");
    // "t:  long step" is 13 characters, "t:  short" 9: four blanks.
    EXPECT_EQ(f.text(), "\rt:  long step\rt:  short    ");
}

TEST(ProgressLine, EndsTheLineBeforeAnythingElseIsPrinted) {
    Fixture f;
    {
        ProgressLine line("t", f.settings());
        f.now = 0.9;
        line.update(0.5, "x");
        // An error unwinding through the command destroys the line: one newline.
    }
    EXPECT_EQ(f.text(), "\rt: 50%  x\n");
}

TEST(ProgressLine, FinishShowsTheWholeAndEndsOnce) {
    Fixture f;
    ProgressLine line("t", f.settings());
    f.now = 0.9;
    line.update(0.5, "x");
    f.now = 3.0;
    line.finish();
    line.end();  // already ended: nothing more
    EXPECT_EQ(f.text(), "\rt: 50%  x\rt: 100%  done in 3s\n");
}

TEST(ProgressLine, AQuickCommandAndADisabledLineWriteNothing) {
    Fixture quick;
    {
        ProgressLine line("t", quick.settings());
        line.update(0.5, "x");
        quick.now = 0.4;
        line.finish();
    }
    EXPECT_EQ(quick.text(), "");
    Fixture off;
    {
        ProgressLine line("t", off.settings(false));
        off.now = 5.0;
        line.update(0.5, "x");
        line.finish();
    }
    EXPECT_EQ(off.text(), "");
}

}  // namespace
}  // namespace stochtex::cli
