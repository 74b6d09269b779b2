// progressPart (core/progress.h): a part's fractions mapped into its range
// of the parent's, and its name put before the steps it reports.
#include "stochtex/core/progress.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace stochtex {
namespace {

struct Recorder {
    std::vector<std::pair<double, std::string>> calls;
    Progress callback() {
        return [this](double f, const std::string& s) { calls.emplace_back(f, s); };
    }
};

TEST(ProgressPart, MapsFractionsIntoItsRange) {
    Recorder r;
    const Progress part = progressPart(r.callback(), 0.2, 0.6);
    part(0.0, "");
    part(0.5, "");
    part(1.0, "");
    ASSERT_EQ(r.calls.size(), 3u);
    // 1e-12: double arithmetic on values of order 1.
    EXPECT_NEAR(r.calls[0].first, 0.2, 1e-12);
    EXPECT_NEAR(r.calls[1].first, 0.4, 1e-12);
    EXPECT_NEAR(r.calls[2].first, 0.6, 1e-12);
}

TEST(ProgressPart, NamesItsStepsAndAnnouncesItselfOnce) {
    Recorder r;
    const Progress part = progressPart(r.callback(), 1, 4, "figure4");
    part(0.0, "");           // the first report names the part
    part(0.5, "reference");  // a step inside it
    part(0.7, "");           // keeps the step shown
    ASSERT_EQ(r.calls.size(), 3u);
    EXPECT_EQ(r.calls[0].second, "figure4");
    EXPECT_EQ(r.calls[1].second, "figure4: reference");
    EXPECT_EQ(r.calls[2].second, "");
    EXPECT_NEAR(r.calls[1].first, 0.25 + 0.5 * 0.25, 1e-12);
}

TEST(ProgressPart, NestsAndStaysEmptyWithoutAParent) {
    Recorder r;
    const Progress inner = progressPart(progressPart(r.callback(), 0.5, 1.0, "all"), 0.0, 0.5, "table1");
    inner(0.5, "footprint 2/4");
    ASSERT_EQ(r.calls.size(), 1u);
    EXPECT_NEAR(r.calls[0].first, 0.625, 1e-12);  // 0.5 + 0.5 · (0.5 · 0.5)
    EXPECT_EQ(r.calls[0].second, "all: table1: footprint 2/4");
    EXPECT_FALSE(progressPart(Progress{}, 0.0, 1.0, "x"));
}

}  // namespace
}  // namespace stochtex
