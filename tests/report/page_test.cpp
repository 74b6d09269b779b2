#include "stochtex/report/page.h"

#include <gtest/gtest.h>

namespace stochtex {
namespace {

size_t count(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t p = 0; (p = s.find(what, p)) != std::string::npos; p += what.size()) ++n;
    return n;
}

Figure errorsChart() {
    PlotSeries a{"ours", {1, 2, 4}, {0.5, 0.25, 0.125}, {1, 0, 0}},
        b{"theirs", {1, 2, 4}, {0.5, 0.25, 0.125}, {0, 0, 1}};
    LinePlotOptions o;
    o.title = "mean |μ̂ error| </script><b>";
    o.logX = true;
    return {"errors.png", Image(4, 4, 3, 1.0f), "Errors.", LineChart{{a, b}, o}};
}

// The preview of a video beside its figures: the animated WebP shown, the
// MP4 linked, the caption as given (HTML) and the paths escaped.
TEST(Page, AnimatedPreviewShowsTheWebpAndLinksTheVideo) {
    EXPECT_EQ(htmlAnimatedPreview("marble/", "sliding_<x>", "<b>s</b>"),
              "<figure><img src='marble/sliding_&lt;x&gt;.webp'><figcaption><b>s</b> (animated; full resolution in "
              "<a href='marble/sliding_&lt;x&gt;.mp4'>sliding_&lt;x&gt;.mp4</a>).</figcaption></figure>");
}

TEST(Page, ChartsAreInlinedSelfContainedAndDeterministic) {
    const std::vector<Figure> figures{errorsChart(), {"map.png", Image(4, 4, 3, 0.0f), "A map."}};
    const std::string body = htmlFigures("sub/", figures);
    EXPECT_EQ(count(body, "<canvas>"), 1u);
    EXPECT_EQ(count(body, "<img src='sub/map.png'>"), 1u);
    EXPECT_EQ(count(body, "href='sub/errors.png'"), 1u);  // the PNG stays one click away
    EXPECT_NE(body.find("\"label\":\"theirs (same values as ours)\""), std::string::npos);
    EXPECT_NE(body.find("\"type\":\"logarithmic\""), std::string::npos);  // the x axis
    EXPECT_NE(body.find("μ̂"), std::string::npos);
    // The legend flows below the plot, never clipped at a narrow canvas's edge.
    EXPECT_NE(body.find("\"legend\":{\"position\":\"bottom\"}"), std::string::npos);
    EXPECT_EQ(count(body, "</script>"), 1u);  // the title's "</script>" is escaped inside the JSON
    const std::string page = htmlPage("t", body);
    EXPECT_EQ(count(page, "Chart.js v3"), 1u);  // the library itself, not a link to it
    EXPECT_EQ(page.find("src='http"), std::string::npos);
    EXPECT_EQ(page.find("<script src"), std::string::npos);
    EXPECT_EQ(page, htmlPage("t", htmlFigures("sub/", figures)));
    // A page without charts carries no script.
    EXPECT_EQ(htmlPage("t", htmlFigures("", {figures[1]})).find("<script"), std::string::npos);
}

// A rate that is constant up to its 6th digit is a flat line in the PNG and
// in the chart alike: the y axis starts at 0 (Chart.js fitted 0.0338935–
// 0.0338980 and a constant read as a fall), and ticks read as the PNG's.
TEST(Page, ChartAxesAreThePngsAndConstantsLookFlat) {
    PlotSeries rate{"expansion rate", {0, 1, 2, 3}, {0.0338980, 0.0338960, 0.0338950, 0.0338935}, {1, 0, 0}};
    LinePlotOptions o;
    const PlotRange r = linePlotRange({rate}, o);
    EXPECT_EQ(r.y0, 0.0);
    EXPECT_NEAR(r.y1, 1.05 * 0.0338980, 1e-12);
    EXPECT_EQ(r.x0, 0.0);
    EXPECT_EQ(r.x1, 3.0);
    const std::string body = htmlFigures("", {{"rate.png", Image(4, 4, 3, 1.0f), "Rate.", LineChart{{rate}, o}}});
    EXPECT_NE(body.find("\"y\":{\"type\":\"linear\",\"title\":{\"display\":false,\"text\":\"\"},\"min\":0.0,"),
              std::string::npos)
        << body;
    EXPECT_NE(htmlPage("t", body).find("callback:function(v,i,t)"), std::string::npos);
    EXPECT_EQ(tickLabel(0.125), "0.125");
    EXPECT_EQ(tickLabel(2.5e-4), "2.5×10⁻⁴");
    EXPECT_EQ(tickLabel(1e-9), "10⁻⁹");
    EXPECT_EQ(tickLabel(-12345), "−1.2×10⁴");
}

}  // namespace
}  // namespace stochtex
