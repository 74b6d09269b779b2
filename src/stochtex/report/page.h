#pragma once
// The report pages (`analyze`, `reproduce all`) and the files of a study:
// figures with captions, the HTML page frame, output folders.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "stochtex/core/base64.h"
#include "stochtex/image/image.h"
#include "stochtex/report/plot.h"

namespace stochtex {

// One image a study made: its file name in the study's folder and what it
// shows (an empty caption: written, but not shown on report pages). Figures
// are display images: values are the file's codes (plots, sheets, data shown
// as grey), so a linear colour render goes in through srgbFromLinear.
// A line plot also carries its data (chart): report pages then draw it as an
// interactive chart, with the PNG one click away.
struct Figure {
    std::string file;
    Image image;
    std::string caption;
    std::optional<LineChart> chart = std::nullopt;
};

// A line plot described once: its PNG (linePlot) and the page's interactive
// chart both come from `chart`.
Figure chartFigure(std::string file, LineChart chart, std::string caption);

// Creates dir (and parents); InputError naming it if that fails.
void ensureFolder(const std::string& dir);

// Writes the figure's image into dir (PNG or EXR by the file's extension).
void writeFigure(const std::string& dir, const Figure& figure);
void writeFigures(const std::string& dir, const std::vector<Figure>& figures);

// Writes text to dir/file atomically (CSV, Markdown, HTML).
void writeText(const std::string& dir, const std::string& file, const std::string& text);

// <figure> elements linking to prefix + file for the captioned figures,
// at most `limit` of them; a figure with a chart is a Chart.js canvas whose
// configuration is inlined as JSON (htmlPage adds the library).
std::string htmlFigures(const std::string& prefix, const std::vector<Figure>& figures, size_t limit = SIZE_MAX);

// A <figure> showing the animated preview prefix + name + ".webp" of a video
// (FrameSequenceWriter), captioned `caption` (HTML) and linking to the MP4.
std::string htmlAnimatedPreview(const std::string& prefix, const std::string& name, const std::string& caption);

// A figure-like image (values are the file's codes, as in writeFigures) as
// an 8-bit PNG in a data: URI, for pages that must be one file.
std::string pngDataUri(const Image& image);

// A whole page: <head> with the report style (content at most maxWidthPx
// wide, figure captions at most captionWidthPx), then body (HTML) unchanged;
// when the body has charts, Chart.js (Debian's libjs-chart.js, embedded at
// build time) and the few lines that start them are inlined, so the page
// stays self-contained and the same bytes on every run.
std::string htmlPage(const std::string& title, const std::string& body, int maxWidthPx = 1200,
                     int captionWidthPx = 560);

}  // namespace stochtex
