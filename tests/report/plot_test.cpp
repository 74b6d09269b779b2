#include "stochtex/report/plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace stochtex {
namespace {

// A pixel differs from the white background by more than 1/255 in a channel.
bool ink(const Image& im, int x, int y) {
    for (int k = 0; k < 3; ++k)
        if (im.at(x, y, k) < 254.0f / 255.0f) return true;
    return false;
}

int inkCount(const Image& im, const PixelBox& b) {
    int n = 0;
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) n += ink(im, x, y);
    return n;
}

// Pixels within 40/255 of an RGB colour (anti-aliased edges excluded).
int colourCount(const Image& im, const PixelBox& b, const std::array<float, 3>& c) {
    int n = 0;
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) {
            bool near = true;
            for (int k = 0; k < 3; ++k) near = near && std::abs(im.at(x, y, k) - c[size_t(k)]) < 40.0f / 255.0f;
            n += near;
        }
    return n;
}

bool inside(const PixelBox& b, const Image& im) {
    return b.x0 >= 0 && b.y0 >= 0 && b.x1 <= im.width() && b.y1 <= im.height() && !b.empty();
}

PlotSeries line(const std::string& name, std::array<float, 3> colour, double slope) {
    PlotSeries s{name, {}, {}, colour};
    for (int i = 0; i <= 8; ++i) {
        s.x.push_back(i);
        s.y.push_back(slope * i);
    }
    return s;
}

TEST(Plot, LongLegendStaysInsideTheImageBesideTheAxes) {
    const std::string longName(90, 'W');
    LinePlotOptions o;
    o.title = "legend test";
    PlotLayout layout;
    const Image im =
        linePlot({line("short", {0.8f, 0.2f, 0.1f}, 1), line(longName, {0.1f, 0.3f, 0.8f}, 2)}, o, &layout);
    ASSERT_TRUE(inside(layout.legend, im));
    ASSERT_TRUE(inside(layout.plotArea, im));
    EXPECT_GE(layout.legend.x0, layout.plotArea.x1);  // beside the axes, never over the curves
    EXPECT_GT(im.width(), o.width);                   // the image grew for the legend
    // The legend's ink (text included) ends at its box, and nothing touches the image's right edge.
    int rightmost = -1;
    for (int y = layout.legend.y0; y < layout.legend.y1; ++y)
        for (int x = layout.legend.x0; x < im.width(); ++x)
            if (ink(im, x, y)) rightmost = std::max(rightmost, x);
    EXPECT_GE(rightmost, layout.legend.x1 - 2);  // the box's right border
    EXPECT_LT(rightmost, layout.legend.x1 + 1);
    for (int y = 0; y < im.height(); ++y) EXPECT_FALSE(ink(im, im.width() - 1, y)) << "row " << y;
    // The long entry's text reaches close to the box's right border (it was measured, not guessed).
    const int textRow = layout.legend.y0 + 6 + 18 + 9;
    int textRight = -1;
    for (int x = layout.legend.x0; x < layout.legend.x1 - 2; ++x)
        for (int dy = -4; dy <= 4; ++dy)
            if (ink(im, x, textRow + dy)) textRight = std::max(textRight, x);
    EXPECT_GT(textRight, layout.legend.x1 - 20);
}

TEST(Plot, IdenticalSeriesBothStayVisible) {
    const std::array<float, 3> red{0.9f, 0.1f, 0.1f}, blue{0.1f, 0.2f, 0.9f};
    PlotLayout layout;
    const Image both = linePlot({line("ours", red, 1), line("theirs", blue, 1)}, LinePlotOptions{}, &layout);
    const PixelBox& a = layout.plotArea;
    const int redPixels = colourCount(both, a, red), bluePixels = colourCount(both, a, blue);
    // Alone, the red curve covers this many pixels; drawn under an identical
    // blue one it keeps a good part of them (the blue one is dashed).
    const Image alone = linePlot({line("ours", red, 1)}, LinePlotOptions{});
    const int redAlone = colourCount(alone, a, red);
    EXPECT_GT(redAlone, 400);
    EXPECT_GT(redPixels, redAlone / 4);
    EXPECT_GT(bluePixels, redAlone / 4);
    // The legend says they coincide: its entry is longer than without the note.
    PlotLayout apart;
    linePlot({line("ours", red, 1), line("theirs", blue, 2)}, LinePlotOptions{}, &apart);
    EXPECT_GT(layout.legend.x1 - layout.legend.x0, apart.legend.x1 - apart.legend.x0 + 50);
}

TEST(Plot, UnicodeLabelsRenderAsGlyphs) {
    // Same title in Greek with combining hats, in ASCII stand-ins, and in
    // characters no font has (which render as the fallback box): the three
    // differ and the Greek one has ink where the title is.
    LinePlotOptions o;
    auto titleBand = [](const Image& im) { return PixelBox{0, 0, im.width(), 24}; };
    o.title = "μ̂ σ̂ S̄";
    const Image greek = linePlot({line("a", {0, 0, 0}, 1)}, o);
    o.title = "mu sigma S-";
    const Image ascii = linePlot({line("a", {0, 0, 0}, 1)}, o);
    o.title = "\U000F0001 \U000F0002 \U000F0003";
    const Image missing = linePlot({line("a", {0, 0, 0}, 1)}, o);
    const int inkGreek = inkCount(greek, titleBand(greek));
    EXPECT_GT(inkGreek, 40);
    auto differing = [&](const Image& a, const Image& b) {
        int n = 0;
        const PixelBox t = titleBand(a);
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < std::min(a.width(), b.width()); ++x) n += ink(a, x, y) != ink(b, x, y);
        return n;
    };
    EXPECT_GT(differing(greek, ascii), 20);
    EXPECT_GT(differing(greek, missing), 20);
    // Captions of sheets too.
    const Image tile(32, 32, 3, 0.5f);
    const Image g = sheet({{tile}}, {{"μ̂ σ̂"}}), q = sheet({{tile}}, {{"? ?"}});
    ASSERT_EQ(g.width(), q.width());
    int diff = 0;
    for (int y = 42; y < g.height(); ++y)
        for (int x = 0; x < g.width(); ++x) diff += ink(g, x, y) != ink(q, x, y);
    EXPECT_GT(diff, 10);
}

TEST(Plot, SheetCaptionsWrapInsideTheirColumns) {
    // Tiny images with long captions (reproduce … --size 64 gives 64-pixel
    // thumbnails): each caption wraps within its column, so the gaps between
    // columns stay blank.
    const Image tile(24, 24, 3, 0.0f);
    const std::vector<std::string> caps{"error, estim. 128² long caption words", "reference 128² and more words",
                                        "exact stats 128²"};
    const Image s = sheet({{tile, tile, tile}}, {caps});
    const int pad = 10, col = kSheetMinCaptionWidth;
    ASSERT_EQ(s.width(), pad + 3 * (col + pad));
    const int captionTop = pad + 24;
    EXPECT_GT(s.height(), captionTop + 2 * 12);  // wrapped onto two lines or more
    for (int c = 0; c < 2; ++c) {
        const int gap0 = pad + c * (col + pad) + col;
        EXPECT_EQ(inkCount(s, {gap0, captionTop, gap0 + pad, s.height()}), 0) << "gap after column " << c;
    }
    for (int c = 0; c < 3; ++c) {
        const int x0 = pad + c * (col + pad);
        EXPECT_GT(inkCount(s, {x0, captionTop, x0 + col, s.height()}), 30) << "caption " << c;
    }
    // Images sit centred in their columns.
    EXPECT_TRUE(ink(s, pad + (col - 24) / 2 + 1, pad + 1));
    EXPECT_FALSE(ink(s, pad + 2, pad + 1));
}

TEST(Plot, HeatmapColoursAxesAndColourBar) {
    Image v(4, 2, 1);
    for (int x = 0; x < 4; ++x) {
        v.at(x, 0) = float(x) / 3.0f;  // 0 … 1
        v.at(x, 1) = -1.0f;
    }
    v.at(3, 1) = std::nanf("");
    HeatmapOptions o;
    o.title = "Corr[I(x,0), I(y,0)] — a long title for a small map";
    o.xLabel = "x";
    o.yLabel = "y";
    o.vmin = -1;
    o.vmax = 1;
    o.cell = 20;
    PlotLayout layout;
    const Image im = heatmapPlot(v, o, &layout);
    ASSERT_TRUE(inside(layout.plotArea, im));
    ASSERT_TRUE(inside(layout.legend, im));
    EXPECT_EQ(layout.plotArea.x1 - layout.plotArea.x0, 80);
    EXPECT_EQ(layout.plotArea.y1 - layout.plotArea.y0, 40);
    for (int y = 0; y < im.height(); ++y) EXPECT_FALSE(ink(im, im.width() - 1, y)) << "row " << y;
    const Image expected = colourise(v, -1, 1, HeatPalette::Diverging);
    // yUp: row 0 of the values is the bottom row of cells.
    auto cellColour = [&](int x, int y) {
        const int px = layout.plotArea.x0 + x * 20 + 10, py = layout.plotArea.y1 - 1 - y * 20 - 10;
        return std::array<float, 3>{im.at(px, py, 0), im.at(px, py, 1), im.at(px, py, 2)};
    };
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 2; ++y)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(cellColour(x, y)[size_t(k)], expected.at(x, y, k), 3.0f / 255.0f) << x << "," << y;
    EXPECT_NEAR(cellColour(3, 1)[0], 128.0f / 255.0f, 2.0f / 255.0f);  // NaN: grey
    EXPECT_NEAR(cellColour(3, 1)[2], 128.0f / 255.0f, 2.0f / 255.0f);
    // The colour bar runs from vmin (bottom) to vmax (top) through the palette.
    // Rows near its ends hold values ~1/16 of the range in from vmax / vmin.
    const PixelBox& bar = layout.legend;
    const int bx = bar.x0 + 8, barH = bar.y1 - bar.y0;
    Image near(1, 2, 1);
    near.at(0, 0) = float(1.0 - 2.0 * 2.5 / barH);   // row y0 + 2
    near.at(0, 1) = float(-1.0 + 2.0 * 2.5 / barH);  // row y1 − 3
    const Image nearColours = colourise(near, -1, 1, HeatPalette::Diverging);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(im.at(bx, bar.y0 + 2, k), nearColours.at(0, 0, k), 10.0f / 255.0f);
        EXPECT_NEAR(im.at(bx, bar.y1 - 3, k), nearColours.at(0, 1, k), 10.0f / 255.0f);
    }
}

TEST(Plot, ColourLegendWidensForItsTitle) {
    const Image narrow = colourLegend(0, 1, HeatPalette::Viridis, "error", 200);
    EXPECT_EQ(narrow.width(), 200);
    const Image wide = colourLegend(0, 1, HeatPalette::Viridis, std::string(60, 'M'), 200);
    EXPECT_GT(wide.width(), 400);
    for (int y = 0; y < wide.height(); ++y) EXPECT_FALSE(ink(wide, wide.width() - 1, y));
}

TEST(Plot, LogAxesAndBarsDraw) {
    PlotSeries s{
        "errors", {1, 2, 4, 8, 16, 32, 64, 128}, {0.2, 0.1, 0.05, 0.02, 0.01, 0.004, 0.002, 0.001}, {0.1f, 0.6f, 0.2f}};
    LinePlotOptions o;
    o.logX = o.logY = true;
    PlotLayout layout;
    const Image im = linePlot({s}, o, &layout);
    EXPECT_GT(colourCount(im, layout.plotArea, s.colour), 200);
    PlotSeries h{"", {0.25, 0.75}, {0.5, 1.0}, {0.8f, 0.2f, 0.1f}, true};
    const Image bars = linePlot({h}, LinePlotOptions{}, &layout);
    EXPECT_TRUE(layout.legend.empty());  // unnamed series: no legend
    const int area = (layout.plotArea.x1 - layout.plotArea.x0) * (layout.plotArea.y1 - layout.plotArea.y0);
    EXPECT_GT(colourCount(bars, layout.plotArea, h.colour), area / 3);  // two bars covering ~half the area
}

TEST(Plot, ConcurrentCallsGiveTheSerialImages) {
    // PLplot keeps global state; the plot functions serialise themselves.
    auto draw = [](int i) {
        LinePlotOptions o;
        o.title = "thread " + std::to_string(i);
        return linePlot({line("s", {0.8f, 0.2f, 0.1f}, i + 1)}, o);
    };
    std::vector<Image> serial, parallel(4);
    for (int i = 0; i < 4; ++i) serial.push_back(draw(i));
    std::vector<std::thread> threads;
    for (int i = 0; i < 4; ++i) threads.emplace_back([&, i] { parallel[size_t(i)] = draw(i); });
    for (auto& t : threads) t.join();
    for (int i = 0; i < 4; ++i) EXPECT_EQ(serial[size_t(i)].data(), parallel[size_t(i)].data()) << i;
}

}  // namespace
}  // namespace stochtex
