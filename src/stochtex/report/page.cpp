#include "stochtex/report/page.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "stochtex/core/embedded_file.h"
#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/table.h"

namespace stochtex {

Figure chartFigure(std::string file, LineChart chart, std::string caption) {
    Image image = linePlot(chart.series, chart.options);
    return Figure{std::move(file), std::move(image), std::move(caption), std::move(chart)};
}

void ensureFolder(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) throw InputError(dir + ": cannot create output folder");
}

void writeFigure(const std::string& dir, const Figure& figure) {
    writeImage((std::filesystem::path(dir) / figure.file).string(), figure.image, kNoTransfer);
}

void writeFigures(const std::string& dir, const std::vector<Figure>& figures) {
    for (const auto& f : figures) writeFigure(dir, f);
}

void writeText(const std::string& dir, const std::string& file, const std::string& text) {
    writeFileAtomic((std::filesystem::path(dir) / file).string(), text);
}

extern const EmbeddedFile kEmbeddedChartJs[];
extern const std::size_t kEmbeddedChartJsCount;

namespace {

constexpr const char* kChartClass = "stochtex-chart";

std::string cssColour(const std::array<float, 3>& c) {
    auto byte = [](float v) { return std::to_string(std::lround(255.0 * std::clamp(v, 0.0f, 1.0f))); };
    return "rgb(" + byte(c[0]) + "," + byte(c[1]) + "," + byte(c[2]) + ")";
}

nlohmann::ordered_json axis(const std::string& title, bool log, double lo, double hi) {
    nlohmann::ordered_json a;
    a["type"] = log ? "logarithmic" : "linear";
    a["title"] = {{"display", !title.empty()}, {"text", title}};
    if (std::isfinite(lo)) a["min"] = lo;
    if (std::isfinite(hi)) a["max"] = hi;
    return a;
}

// The Chart.js configuration of a line plot: the PNG's series, colours, dash
// patterns and markers (by series index, as linePlot draws them) and labels.
std::string chartConfig(const LineChart& c) {
    static const char* markers[6] = {"circle", "rect", "triangle", "rectRot", "triangle", "circle"};
    static const std::vector<int> dashes[4] = {{}, {6, 4}, {12, 6}, {12, 3, 3, 3}};
    const LinePlotOptions& o = c.options;
    const std::vector<std::string> labels = seriesLabels(c.series);
    nlohmann::ordered_json datasets = nlohmann::ordered_json::array();
    for (size_t i = 0; i < c.series.size(); ++i) {
        const PlotSeries& s = c.series[i];
        nlohmann::ordered_json points = nlohmann::ordered_json::array();
        for (size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) {
            if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) continue;  // JSON has no NaN
            if ((o.logX && !(s.x[k] > 0)) || (o.logY && !(s.y[k] > 0))) continue;
            points.push_back({{"x", s.x[k]}, {"y", s.y[k]}});
        }
        const bool marked = points.size() <= 16;
        nlohmann::ordered_json d;
        d["label"] = labels[i];
        d["data"] = std::move(points);
        d["showLine"] = true;
        d["borderColor"] = d["backgroundColor"] = cssColour(s.colour);
        d["borderWidth"] = 2;
        if (s.bars)
            d["stepped"] = "middle";
        else
            d["borderDash"] = dashes[i % 4];
        d["pointStyle"] = markers[i % 6];
        d["pointRadius"] = marked ? 4 : 0;
        d["pointBackgroundColor"] = i == 0 ? cssColour(s.colour) : "rgba(0,0,0,0)";
        datasets.push_back(std::move(d));
    }
    nlohmann::ordered_json cfg;
    cfg["type"] = "scatter";
    cfg["data"]["datasets"] = std::move(datasets);
    auto& opt = cfg["options"];
    opt["animation"] = false;
    opt["plugins"]["title"] = {{"display", !o.title.empty()}, {"text", o.title}};
    // Below the plot: Chart.js flows a bottom legend onto as many rows as its
    // labels need, where a right-hand legend in a caption-wide canvas gets
    // truncated labels (seen in headless Chromium).
    opt["plugins"]["legend"] = {{"position", "bottom"}};
    // The PNG's axis ranges: Chart.js would fit a constant's last digits.
    const PlotRange r = linePlotRange(c.series, o);
    opt["scales"]["x"] = axis(o.xLabel, o.logX, r.x0, r.x1);
    opt["scales"]["y"] = axis(o.yLabel, o.logY, r.y0, r.y1);
    std::string json = cfg.dump();
    // Inside <script>, "</" would end the element early.
    for (size_t p = 0; (p = json.find("</", p)) != std::string::npos; p += 3) json.replace(p, 2, "<\\/");
    return json;
}

}  // namespace

std::string htmlAnimatedPreview(const std::string& prefix, const std::string& name, const std::string& caption) {
    const std::string path = htmlEscape(prefix + name);
    return "<figure><img src='" + path + ".webp'><figcaption>" + caption + " (animated; full resolution in <a href='" +
           path + ".mp4'>" + htmlEscape(name) + ".mp4</a>).</figcaption></figure>";
}

std::string htmlFigures(const std::string& prefix, const std::vector<Figure>& figures, size_t limit) {
    std::ostringstream h;
    size_t shown = 0;
    for (const auto& f : figures) {
        if (f.caption.empty()) continue;
        if (shown++ == limit) break;
        if (f.chart) {
            h << "<figure class='chart'><canvas></canvas><script type='application/json' class='" << kChartClass << "'>"
              << chartConfig(*f.chart) << "</script><figcaption>" << htmlEscape(f.caption) << " (<a href='" << prefix
              << f.file << "'>PNG</a>)</figcaption></figure>\n";
        } else {
            h << "<figure><a href='" << prefix << f.file << "'><img src='" << prefix << f.file << "'></a><figcaption>"
              << htmlEscape(f.caption) << "</figcaption></figure>\n";
        }
    }
    return h.str();
}

std::string pngDataUri(const Image& image) {
    return "data:image/png;base64," + base64(encodeImage("image.png", image, kNoTransfer));
}

std::string htmlPage(const std::string& title, const std::string& body, int maxWidthPx, int captionWidthPx) {
    std::ostringstream h;
    h << "<!doctype html><html><head><meta charset='utf-8'><title>" << htmlEscape(title)
      << "</title><style>body{font-family:sans-serif;max-width:" << maxWidthPx
      << "px;margin:2em auto;color:#222}"
         "figure{display:inline-block;margin:0 1em 1.5em 0;vertical-align:top;max-width:100%}"
         // A thin frame: a white figure (a validity mask that holds everywhere) reads as a picture, not a gap.
         "img{max-width:100%}figure img{border:1px solid #ccc}figcaption{max-width:"
      << captionWidthPx
      << "px;font-size:90%}table{border-collapse:collapse;margin:.5em 0 1.5em}"
         "td,th{border:1px solid #bbb;padding:.25em .6em;text-align:right}"
         "figure.chart{width:"
      << captionWidthPx << "px}</style></head><body>" << body;
    if (body.find(kChartClass) != std::string::npos) {
        if (kEmbeddedChartJsCount != 1) throw std::logic_error("htmlPage: Chart.js is not embedded");
        h << "<script>" << kEmbeddedChartJs[0].contents << "</script><script>document.querySelectorAll('script."
          << kChartClass
          << "').forEach(function(s){var c=JSON.parse(s.textContent);"
             // Linear axes' ticks in the PNG's number format (tickLabel):
             // 3 significant digits, powers of ten outside [0.01, 10⁴), and
             // 0 for a tick that is zero up to Chart.js's rounding.
             "['x','y'].forEach(function(k){var a=c.options.scales[k];if(a.type==='linear')a.ticks={callback:"
             "function(v,i,t){var span=Math.abs(t[t.length-1].value-t[0].value)||1,m=Math.abs(v);"
             "if(m<1e-9*span)return '0';var sign=v<0?'\u2212':'';"
             "if(m>=1e4||m<1e-2){var e=Math.floor(Math.log10(m)+1e-9),f=m/Math.pow(10,e),"
             "sup=String(e).replace(/-/g,'\u207b').replace(/[0-9]/g,function(d){return '\u2070\u00b9\u00b2\u00b3"
             "\u2074\u2075\u2076\u2077\u2078\u2079'[d];});"
             "return sign+(Math.abs(f-1)<1e-6?'':parseFloat(f.toPrecision(2))+'\u00d7')+'10'+sup;}"
             "return sign+parseFloat(m.toPrecision(3));}};});"
             "new Chart(s.parentNode.querySelector('canvas'),c);});"
             "</script>";
    }
    h << "</body></html>\n";
    return h.str();
}

}  // namespace stochtex
