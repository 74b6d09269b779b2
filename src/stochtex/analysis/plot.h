#pragma once
// Figures for reports: heat maps with axes and a colour legend, and line /
// bar plots, drawn with OpenCV's imgproc primitives into RGB Images.
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

// Text in plots is drawn with OpenCV's Hershey fonts: ASCII only.
struct HeatmapOptions {
    std::string title;
    std::string xLabel, yLabel;
    double vmin = -1, vmax = 1;       // colour scale (values outside are clamped)
    double xMin = 0, xMax = 1;        // axis ranges the columns / rows span
    double yMin = 0, yMax = 1;
    bool yUp = true;                  // row 0 drawn at the bottom (mathematical axes)
    HeatPalette palette = HeatPalette::Diverging;
    int cell = 0;                     // pixels per value; 0 = fit the plot to ~512 px
};
// values: 1-channel.
Image heatmapPlot(const Image& values, const HeatmapOptions& o);
// The values through the palette alone (no axes), one pixel per value, row 0
// at the top as stored.
Image colourise(const Image& values, double vmin, double vmax, HeatPalette palette);

// A horizontal colour bar from vmin to vmax with ticks and a title (ASCII:
// the plot fonts have no other glyphs), for sheets of colourised maps.
Image colourLegend(double vmin, double vmax, HeatPalette palette, const std::string& title, int width = 420);

struct PlotSeries {
    std::string name;
    std::vector<double> x, y;
    std::array<float, 3> colour{0.1f, 0.3f, 0.8f};  // RGB in [0, 1]
    bool bars = false;                              // histogram-style bars instead of a line
};

struct LinePlotOptions {
    std::string title, xLabel, yLabel;
    int width = 560, height = 360;
    bool logX = false, logY = false;
    // Axis ranges; NaN = from the data.
    double xMin = std::numeric_limits<double>::quiet_NaN(), xMax = std::numeric_limits<double>::quiet_NaN();
    double yMin = std::numeric_limits<double>::quiet_NaN(), yMax = std::numeric_limits<double>::quiet_NaN();
    // Shaded vertical bands [a, b] (e.g. the clamped intervals of a curve).
    std::vector<std::array<double, 2>> bands;
};
Image linePlot(const std::vector<PlotSeries>& series, const LinePlotOptions& o);

// Histogram of a 1-channel image over [lo, hi] in `bins` bins, as fractions.
std::vector<double> histogram(const Image& image, int bins, double lo = 0.0, double hi = 1.0);

// Pastes images side by side / below each other on a white sheet, with a
// caption under each (one row per inner vector).
Image sheet(const std::vector<std::vector<Image>>& rows, const std::vector<std::vector<std::string>>& captions);

}  // namespace stochtex
