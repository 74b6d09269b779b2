// A report as a value: one writer for every study's folder and page, and
// merged reports (reproduce all, analyze) that keep each part's files in
// its folder.
#include "stochtex/report/report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "stochtex/image/image_io.h"
#include "test_util.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t count(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t p = 0; (p = s.find(what, p)) != std::string::npos; p += what.size()) ++n;
    return n;
}

Report spectrumLikeReport() {
    Report r;
    r.title = "Power spectrum: a <b>";
    r.html = "<p>Intro.</p>";
    ReportSection s;
    Table summary;
    summary.columns = {{"peak", "peak", ""}};
    summary.add({TableCell::value(0.25)});
    Table perFrame;
    perFrame.columns = {{"frame", "frame", ""}};
    perFrame.add({TableCell::integer(3)});
    s.tables = {{"spectrum.csv", summary}, {"frames.csv", perFrame, false}};
    LinePlotOptions o;
    o.title = "Radial profile";
    s.figures = {chartFigure("radial.png", {{{"P", {1, 2, 3}, {3, 2, 1}}}, o}, "Radial."),
                 {"frame.png", Image(8, 4, 3, 0.5f), ""}};
    s.files = {{"notes.md", "# notes\n", ""}};
    r.sections.push_back(s);
    return r;
}

// Every figure, named table and file is written where its section says, the
// page shows the tables on the page, the captioned figures and the title
// escaped, and the list of written files says what is there.
class ReportFolder : public test::ScratchFolder {};

TEST_F(ReportFolder, WritesEverySectionsFilesAndOnePage) {
    const std::vector<std::string> written = writeReport(dir_.string(), spectrumLikeReport());
    EXPECT_EQ(written, (std::vector<std::string>{"radial.png", "frame.png", "spectrum.csv", "frames.csv", "notes.md",
                                                 "index.html"}));
    for (const std::string& f : written) EXPECT_TRUE(fs::exists(dir_ / f)) << f;
    EXPECT_EQ(readImage((dir_ / "frame.png").string()).width(), 8);
    EXPECT_EQ(readText(dir_ / "frames.csv"), "frame\n3\n");
    const std::string page = readText(dir_ / "index.html");
    EXPECT_EQ(count(page, "<h1>Power spectrum: a &lt;b&gt;</h1>"), 1u);
    EXPECT_EQ(count(page, "<table"), 1u);             // the per-frame table is a CSV only
    EXPECT_EQ(count(page, "href='radial.png'"), 1u);  // the chart links its PNG
    EXPECT_EQ(count(page, "frame.png"), 0u);          // uncaptioned: written, not shown
    EXPECT_EQ(listNames(written), "radial.png, frame.png, spectrum.csv, frames.csv, notes.md and index.html");
}

// A merged report keeps each part's files under its folder, links them
// there, and heads each part with the heading given or the part's title.
TEST_F(ReportFolder, MergedPartsKeepTheirFilesInTheirFolders) {
    Report all;
    all.title = "Everything";
    appendReport(all, spectrumLikeReport(), "spectrum", "Power spectrum (Figure 2.22)", "<p>Why.</p>");
    Report second = spectrumLikeReport();
    second.title = "Second part";
    second.sections.front().heading = "Its own heading";
    appendReport(all, second, "second");
    ASSERT_EQ(all.sections.size(), 3u);  // the second part's heading is kept after its title's
    const std::vector<std::string> written = writeReport(dir_.string(), all);
    EXPECT_TRUE(fs::exists(dir_ / "spectrum" / "radial.png"));
    EXPECT_TRUE(fs::exists(dir_ / "second" / "notes.md"));
    EXPECT_FALSE(fs::exists(dir_ / "radial.png"));
    EXPECT_EQ(written.back(), "index.html");
    const std::string page = readText(dir_ / "index.html");
    EXPECT_EQ(count(page, "href='spectrum/radial.png'"), 1u);
    EXPECT_EQ(count(page, "href='second/radial.png'"), 1u);
    EXPECT_LT(page.find("<h2>Power spectrum (Figure 2.22)</h2>\n<p>Why.</p><p>Intro.</p>"), page.find("Second part"));
    EXPECT_LT(page.find("<h2>Second part</h2>"), page.find("<h3>Its own heading</h3>"));
}

// A chart figure is described once: its PNG is linePlot's image of the
// same chart, and the page's chart carries the same series.
TEST(ChartFigure, ThePngAndThePageChartComeFromOneDescription) {
    LinePlotOptions o;
    o.title = "errors";
    const std::vector<PlotSeries> series{{"ours", {1, 2, 4}, {0.5, 0.25, 0.1}}};
    const Figure f = chartFigure("e.png", {series, o}, "Errors.");
    const Image direct = linePlot(series, o);
    EXPECT_EQ(f.image.data(), direct.data());
    ASSERT_TRUE(f.chart.has_value());
    EXPECT_EQ(f.chart->series.front().y, series.front().y);
    EXPECT_EQ(f.chart->options.title, "errors");
}

}  // namespace
}  // namespace stochtex
