#pragma once
// Figures for reports: heat maps with axes and a colour bar, line / bar
// plots, and captioned image sheets, drawn in memory with PLplot (its
// "extcairo" device on a cairo image surface) and Pango, so text is real
// Unicode (μ̂, σ̂, S̄, ‖·‖₂). PLplot keeps global state: every call here is
// serialised by one mutex, so these functions are safe to call from threads.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "stochtex/image/image.h"

namespace stochtex {

enum class HeatPalette {
    Diverging,  // blue – white – red, for signed values (correlations)
    Viridis,    // perceptually uniform, for magnitudes
};

// A rectangle in image pixels: columns [x0, x1), rows [y0, y1), row 0 at the top.
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

// Where a plot put its parts, for callers and tests that check the layout.
struct PlotLayout {
    PixelBox plotArea;  // the axes' frame
    PixelBox legend;    // the legend (or colour bar with its labels); empty when none
};

struct HeatmapOptions {
    std::string title;
    std::string xLabel, yLabel;
    double vmin = -1, vmax = 1;  // colour scale (values outside are clamped)
    double xMin = 0, xMax = 1;   // axis ranges the columns / rows span
    double yMin = 0, yMax = 1;
    bool yUp = true;  // row 0 drawn at the bottom (mathematical axes)
    HeatPalette palette = HeatPalette::Diverging;
    int cell = 0;  // pixels per value; 0 = fit the plot to ~512 px
};
// values: 1-channel; non-finite values are shown grey.
Image heatmapPlot(const Image& values, const HeatmapOptions& o, PlotLayout* layout = nullptr);
// The values through the palette alone (no axes), one pixel per value, row 0
// at the top as stored.
Image colourise(const Image& values, double vmin, double vmax, HeatPalette palette);

// A horizontal colour bar from vmin to vmax with ticks and a title, for
// sheets of colourised maps. The image is `width` wide, or wider when the
// title needs it.
Image colourLegend(double vmin, double vmax, HeatPalette palette, const std::string& title, int width = 420);

struct PlotSeries {
    std::string name;
    std::vector<double> x, y;
    std::array<float, 3> colour{0.1f, 0.3f, 0.8f};  // RGB in [0, 1]
    bool bars = false;                              // histogram-style bars instead of a line
};

// The i-th colour of a categorical palette (10 colours, then repeating),
// for plots whose series are distinct things (filters, variants).
std::array<float, 3> seriesColour(size_t i);

// Every line series gets its own dash pattern and marker (by its index), and
// a series with the same points as an earlier one says so in the legend, so
// coinciding curves stay distinguishable.
struct LinePlotOptions {
    std::string title, xLabel, yLabel;
    int width = 560, height = 360;  // the axes and their labels; a legend widens the image
    bool logX = false, logY = false;
    // Axis ranges; NaN = from the data.
    double xMin = std::numeric_limits<double>::quiet_NaN(), xMax = std::numeric_limits<double>::quiet_NaN();
    double yMin = std::numeric_limits<double>::quiet_NaN(), yMax = std::numeric_limits<double>::quiet_NaN();
    // Shaded vertical bands [a, b] (e.g. the clamped intervals of a curve).
    std::vector<std::array<double, 2>> bands;
};
Image linePlot(const std::vector<PlotSeries>& series, const LinePlotOptions& o, PlotLayout* layout = nullptr);

// The data ranges a line plot's axes show: the options' where set, else the
// data's, a linear y axis from 0 (so a constant is a flat line, not a fall
// over its last digits) with 5 % headroom, log axes over whole decades.
// linePlot draws these and the HTML chart sets them (report/page.h).
struct PlotRange {
    double x0, x1, y0, y1;
};
PlotRange linePlotRange(const std::vector<PlotSeries>& series, const LinePlotOptions& o);
// A tick label as the plots write it: 3 significant digits, a power of ten
// for very large or small magnitudes ("2.5×10⁻⁴"), a real minus sign.
std::string tickLabel(double v);

// The legend text of each series (empty for unnamed ones): its name, plus a
// note naming the earlier series it coincides with, if any.
std::vector<std::string> seriesLabels(const std::vector<PlotSeries>& series);

// A line plot's data and axes, kept beside its PNG so that HTML pages can
// draw it as an interactive chart.
struct LineChart {
    std::vector<PlotSeries> series;
    LinePlotOptions options;
};

// Histogram of a 1-channel image over [lo, hi] in `bins` bins, as fractions.
std::vector<double> histogram(const Image& image, int bins, double lo = 0.0, double hi = 1.0);

// Pastes images side by side / below each other on a white sheet, with a
// caption under each (one row per inner vector). Captions wrap to their
// image's width (never narrower than kSheetMinCaptionWidth pixels, which
// widens the column), so they never overlap.
inline constexpr int kSheetMinCaptionWidth = 96;
Image sheet(const std::vector<std::vector<Image>>& rows, const std::vector<std::vector<std::string>>& captions);

}  // namespace stochtex
