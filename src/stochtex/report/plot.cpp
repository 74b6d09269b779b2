#include "stochtex/report/plot.h"

#include <cairo.h>
#include <pango/pangocairo.h>
#include <plplot.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace stochtex {

namespace {

// ---------------------------------------------------------------------------
// Canvas: a cairo image surface, read back into an Image.

using Rgb = std::array<unsigned char, 3>;
constexpr Rgb kWhite{255, 255, 255}, kInk{40, 40, 40}, kGrid{225, 225, 225}, kBand{255, 200, 200},
    kMissing{128, 128, 128};

// Text sizes in pixels. PLplot's cairo driver sets its Pango font to the
// character height in mm × 96 / 25.4 pixels, so text PLplot draws at kFontPx
// measures the same as textSize(…, kFontPx).
constexpr double kFontPx = 12, kTitlePx = 14, kPxPerMm = 96.0 / 25.4;
constexpr const char* kFontFamily = "sans";

struct Canvas {
    int width, height;
    cairo_surface_t* surface;
    cairo_t* cr;

    Canvas(int w, int h) : width(w), height(h) {
        if (w < 1 || h < 1 || w > 16384 || h > 16384)
            throw std::invalid_argument("plot: image size " + std::to_string(w) + "x" + std::to_string(h) +
                                        " out of range");
        surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
        cr = cairo_create(surface);
        if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
            cairo_destroy(cr);
            cairo_surface_destroy(surface);
            throw std::runtime_error("plot: cannot create a cairo surface");
        }
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
    }
    ~Canvas() {
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    Image image() {
        cairo_surface_flush(surface);
        const unsigned char* data = cairo_image_surface_get_data(surface);
        const int stride = cairo_image_surface_get_stride(surface);
        Image out(width, height, 3, Image::Uninitialized{});
        for (int y = 0; y < height; ++y) {
            const auto* row = reinterpret_cast<const uint32_t*>(data + size_t(y) * size_t(stride));
            for (int x = 0; x < width; ++x) {
                const uint32_t p = row[x];  // RGB24: 0x00RRGGBB in native byte order
                out.at(x, y, 0) = float((p >> 16) & 0xff) / 255.0f;
                out.at(x, y, 1) = float((p >> 8) & 0xff) / 255.0f;
                out.at(x, y, 2) = float(p & 0xff) / 255.0f;
            }
        }
        return out;
    }
};

// Every PLplot call (global state) and, to be safe, every Pango layout.
std::mutex& plotMutex() {
    static std::mutex m;
    return m;
}

struct Layout {
    PangoLayout* layout;
    Layout(cairo_t* cr, const std::string& text, double px, int wrapWidth) {
        layout = pango_cairo_create_layout(cr);
        PangoFontDescription* font = pango_font_description_from_string(kFontFamily);
        pango_font_description_set_absolute_size(font, px * PANGO_SCALE);
        pango_layout_set_font_description(layout, font);
        pango_font_description_free(font);
        pango_layout_set_text(layout, text.c_str(), int(text.size()));
        if (wrapWidth > 0) {
            pango_layout_set_width(layout, wrapWidth * PANGO_SCALE);
            pango_layout_set_wrap(layout, PANGO_WRAP_WORD_CHAR);
            pango_layout_set_alignment(layout, PANGO_ALIGN_CENTER);
        }
    }
    ~Layout() { g_object_unref(layout); }
    Layout(const Layout&) = delete;
    Layout& operator=(const Layout&) = delete;
    std::array<int, 2> size() const {
        PangoRectangle ink, logical;
        pango_layout_get_pixel_extents(layout, &ink, &logical);
        return {logical.width, logical.height};
    }
};

// Width and height in pixels of text in the plot font (wrapped to wrapWidth when > 0). Caller holds the mutex.
std::array<int, 2> textSize(const std::string& text, double px, int wrapWidth = -1) {
    static Canvas* scratch = new Canvas(1, 1);  // only its cairo context is used, under the mutex
    return Layout(scratch->cr, text, px, wrapWidth).size();
}

// ---------------------------------------------------------------------------
// PLplot: one stream per figure, drawing on a Canvas through the "extcairo"
// device (the plplot-driver-cairo package).

void requireCairoDriver() {
    static const bool available = [] {
        // plgDevs fills caller-owned arrays of n entries and sets n to the count.
        std::vector<const char*> menu(256), names(256);
        int n = int(names.size());
        const char** m = menu.data();
        const char** d = names.data();
        plgDevs(&m, &d, &n);
        bool found = false;
        for (int i = 0; i < std::min(n, int(names.size())); ++i) found = found || std::strcmp(d[i], "extcairo") == 0;
        return found;
    }();
    if (!available)
        throw std::runtime_error(
            "plot: PLplot's cairo driver (extcairo) is missing; install plplot-driver-cairo "
            "(scripts/install-deps.sh)");
}

// PLplot's escape character is '#'; a literal one is written twice.
std::string plText(const std::string& s) {
    std::string out;
    for (char c : s) {
        out += c;
        if (c == '#') out += c;
    }
    return out;
}

// cmap0 slots: fixed ones, then one per series.
enum Slot : PLINT { kSlotWhite = 0, kSlotInk, kSlotGrid, kSlotBand, kSlotMissing, kSlotSeries };

void setSlot(PLINT slot, const Rgb& c) { plscol0(slot, c[0], c[1], c[2]); }

Rgb toRgb8(const std::array<float, 3>& c) {
    Rgb out{};
    for (size_t k = 0; k < 3; ++k)
        out[k] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(c[k], 0.0f, 1.0f)));
    return out;
}

class Plplot {
public:
    explicit Plplot(Canvas& canvas, int seriesSlots = 0) : canvas_(canvas) {
        requireCairoDriver();
        plmkstrm(&stream_);
        plsdev("extcairo");
        plspage(0, 0, canvas.width, canvas.height, 0, 0);
        plscmap0n(kSlotSeries + std::max(1, seriesSlots));
        setSlot(kSlotWhite, kWhite);  // slot 0 is the background
        setSlot(kSlotInk, kInk);
        setSlot(kSlotGrid, kGrid);
        setSlot(kSlotBand, kBand);
        setSlot(kSlotMissing, kMissing);
        plinit();
        pl_cmd(PLESC_DEVINIT, canvas.cr);
        pladv(0);
        plschr(kFontPx / kPxPerMm, 1.0);
        plcol0(kSlotInk);
    }
    ~Plplot() { plend1(); }
    Plplot(const Plplot&) = delete;
    Plplot& operator=(const Plplot&) = delete;

    // Viewport = the pixel box, window = the given world range.
    void frame(const PixelBox& b, double x0, double x1, double y0, double y1) const {
        const double w = canvas_.width, h = canvas_.height;
        plvpor(b.x0 / w, b.x1 / w, 1.0 - b.y1 / h, 1.0 - b.y0 / h);
        plwind(x0, x1, y0, y1);
    }
    // The whole canvas in pixel coordinates, y up (world y = height − row).
    void pixels() const { frame({0, 0, canvas_.width, canvas_.height}, 0, canvas_.width, 0, canvas_.height); }
    double row(double y) const { return canvas_.height - y; }

    // Text centred (just 0.5) or left-aligned (0) at pixel (x, row y), vertically centred.
    void text(double x, double y, const std::string& s, double just = 0.5, double px = kFontPx) const {
        pixels();
        plschr(px / kPxPerMm, 1.0);
        plptex(x, row(y), 1, 0, just, plText(s).c_str());
        plschr(kFontPx / kPxPerMm, 1.0);
    }
    void rect(const PixelBox& b, PLINT slot, bool filled) const {
        pixels();
        PLFLT xs[5] = {double(b.x0), double(b.x1), double(b.x1), double(b.x0), double(b.x0)};
        PLFLT ys[5] = {row(b.y0), row(b.y0), row(b.y1), row(b.y1), row(b.y0)};
        plcol0(slot);
        if (filled)
            plfill(4, xs, ys);
        else
            plline(5, xs, ys);
    }

private:
    Canvas& canvas_;
    PLINT stream_ = 0;
};

// ---------------------------------------------------------------------------
// Numbers and ticks.

std::string superscript(int e) {
    static const char* digits[10] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string s = e < 0 ? "⁻" : "";
    for (char c : std::to_string(std::abs(e))) s += digits[c - '0'];
    return s;
}

// A tick label: 3 significant digits, powers of ten for very large / small
// magnitudes, a real minus sign.
std::string number(double v) {
    if (std::abs(v) < 1e-300) return "0";
    const std::string sign = v < 0 ? "−" : "";
    const double a = std::abs(v);
    char buf[32];
    if (a >= 1e4 || a < 1e-2) {
        const int e = int(std::floor(std::log10(a) + 1e-9));
        const double m = a / std::pow(10.0, e);
        if (std::abs(m - 1.0) < 1e-6) return sign + "10" + superscript(e);
        std::snprintf(buf, sizeof buf, "%.2g", m);
        return sign + buf + "×10" + superscript(e);
    }
    std::snprintf(buf, sizeof buf, "%.3g", a);
    return sign + buf;
}

// Step of about `count` (≥ 1) round ticks covering [lo, hi].
double tickStep(double lo, double hi, int count) {
    if (!(hi > lo)) return 1.0;
    const double raw = (hi - lo) / std::max(1, count);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * mag) return m * mag;
    return 10.0 * mag;
}

std::vector<double> ticks(double lo, double hi, int count) {
    std::vector<double> t;
    const double step = tickStep(lo, hi, count);
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
        t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    return t;
}

// One axis: its world range (log10 of the values on a log axis) and labels.
// Up to five ticks, fewer when the axis is short: at most one per
// `tickSpacing` pixels of its `length`, so labels never run into each other.
struct Axis {
    double lo, hi;  // world coordinates
    bool log;
    int length = 400, tickSpacing = 60;  // pixels
    int tickCount() const { return std::clamp(length / tickSpacing, 1, 5); }
    double min() const { return std::min(lo, hi); }  // a flipped axis has lo > hi
    double max() const { return std::max(lo, hi); }
    double step() const { return log ? 0.0 : tickStep(min(), max(), tickCount()); }
    std::vector<std::string> labels() const {
        std::vector<std::string> out;
        if (log) {
            for (double e = std::ceil(min() - 1e-9); e <= max() + 1e-9; e += 1.0)
                out.push_back(number(std::pow(10.0, e)));
        } else {
            for (double t : ticks(min(), max(), tickCount())) out.push_back(number(t));
        }
        return out;
    }
    int labelWidth() const {
        int w = 0;
        for (const auto& s : labels()) w = std::max(w, textSize(s, kFontPx)[0]);
        return w;
    }
    std::string options(const char* base) const { return std::string(base) + "o" + (log ? "l" : ""); }
};

// PLplot's custom tick labels ("o" axis option): our number format. On a log
// axis PLplot passes the exponent.
void labelTicks(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer data) {
    const auto* logs = static_cast<const bool*>(data);
    const bool log = axis == PL_X_AXIS ? logs[0] : logs[1];
    const std::string s = number(log ? std::pow(10.0, value) : value);
    std::snprintf(label, size_t(length), "%s", s.c_str());
}

// Axes frame with ticks and labels, the axis titles beside it. The y title
// sits left of the widest tick label.
void drawAxes(const Plplot& pl, const PixelBox& box, const Axis& x, const Axis& y, const std::string& xLabel,
              const std::string& yLabel, bool grid) {
    static bool logs[2];
    logs[0] = x.log;
    logs[1] = y.log;
    plslabelfunc(labelTicks, logs);
    pl.frame(box, x.lo, x.hi, y.lo, y.hi);
    if (grid) {
        plcol0(kSlotGrid);
        plbox(x.options("g").c_str(), x.step(), 0, y.options("g").c_str(), y.step(), 0);
    }
    plcol0(kSlotInk);
    plwidth(1);
    pllsty(1);
    plbox(x.options("bcnst").c_str(), x.step(), 0, y.options("bcnstv").c_str(), y.step(), 0);
    plslabelfunc(nullptr, nullptr);
    const int cx = (box.x0 + box.x1) / 2;
    if (!xLabel.empty()) pl.text(cx, box.y1 + 2.4 * kFontPx, xLabel);
    if (!yLabel.empty()) {
        pl.frame(box, 0, 1, 0, 1);
        // In character heights, to the title's baseline: past the widest tick
        // label, its gap, and the title's own height (0.9 left the title's
        // letters over labels like "0.06", figure2_6.png).
        const double disp = (y.labelWidth() + 10.0) / kFontPx + 1.6;
        plmtex("l", disp, 0.5, 0.5, plText(yLabel).c_str());
    }
}

// Margins (pixels) around an axes frame with these axes.
struct Margins {
    int left, top, right, bottom;
};
Margins axesMargins(const Axis& y, const std::string& title, const std::string& yLabel) {
    Margins m;
    m.left = y.labelWidth() + 12 + (yLabel.empty() ? 0 : int(1.7 * kFontPx) + 10);
    m.top = title.empty() ? 14 : int(kTitlePx) * 2 + 6;
    m.right = 18;  // half of the last x tick label
    m.bottom = int(3.4 * kFontPx);
    return m;
}

Rgb paletteRgb(HeatPalette p, double t) {
    t = std::clamp(t, 0.0, 1.0);
    if (p == HeatPalette::Diverging) {
        // blue (0) – white (½) – red (1), linear in RGB on each side
        const std::array<double, 3> blue{0.23, 0.30, 0.75}, red{0.75, 0.10, 0.15};
        const auto& end = t < 0.5 ? blue : red;
        const double a = t < 0.5 ? 1.0 - 2.0 * t : 2.0 * t - 1.0;  // 0 at white, 1 at the ends
        Rgb out{};
        for (size_t k = 0; k < 3; ++k)
            out[k] = static_cast<unsigned char>(std::lround(255.0 * (1.0 + a * (end[k] - 1.0))));
        return out;
    }
    cv::Mat one(1, 1, CV_8UC1, cv::Scalar(std::lround(255 * t))), out;
    cv::applyColorMap(one, out, cv::COLORMAP_VIRIDIS);
    const cv::Vec3b c = out.at<cv::Vec3b>(0, 0);
    return {c[2], c[1], c[0]};
}

std::vector<Rgb> paletteLut(HeatPalette p) {
    std::vector<Rgb> lut(256);
    for (int i = 0; i < 256; ++i) lut[size_t(i)] = paletteRgb(p, i / 255.0);
    return lut;
}

// PLplot's cmap1 = the palette, so plimagefr maps [vmin, vmax] through it.
void setPalette(HeatPalette p) {
    const auto lut = paletteLut(p);
    PLINT r[256], g[256], b[256];
    for (size_t i = 0; i < 256; ++i) r[i] = lut[i][0], g[i] = lut[i][1], b[i] = lut[i][2];
    plscmap1n(256);
    plscmap1(r, g, b, 256);
}

// values (nx × ny cells, column-major) drawn over the current window
// [x0, x1] × [y0, y1]; values outside [vmin, vmax] are left out.
void drawImage(const std::vector<double>& values, int nx, int ny, double x0, double x1, double y0, double y1,
               double vmin, double vmax) {
    // plimagefr takes values at the (nx + 1) × (ny + 1) cell corners and
    // paints each cell with its lower-left corner's value: repeat the last
    // column and row.
    std::vector<double> corners(size_t(nx + 1) * size_t(ny + 1));
    std::vector<PLFLT*> columns(static_cast<size_t>(nx + 1));
    for (int i = 0; i <= nx; ++i) {
        columns[size_t(i)] = corners.data() + size_t(i) * size_t(ny + 1);
        for (int j = 0; j <= ny; ++j)
            columns[size_t(i)][j] = values[size_t(std::min(i, nx - 1)) * size_t(ny) + size_t(std::min(j, ny - 1))];
    }
    plimagefr(columns.data(), nx + 1, ny + 1, x0, x1, y0, y1, vmin, vmax, vmin, vmax, nullptr, nullptr);
}

// A colour bar in box: gradient from vmin to vmax along its long side, ticks
// and labels on the right (vertical) or below (horizontal).
void drawColourBar(const Plplot& pl, const PixelBox& box, double vmin, double vmax, bool vertical) {
    const int n = 256;
    std::vector<double> g(n);
    for (int i = 0; i < n; ++i) g[size_t(i)] = vmin + (vmax - vmin) * (i + 0.5) / n;
    const Axis a{vmin, vmax, false, vertical ? box.y1 - box.y0 : box.x1 - box.x0, vertical ? 30 : 60};
    static bool logs[2] = {false, false};
    if (vertical) {
        pl.frame(box, 0, 1, vmin, vmax);
        drawImage(g, 1, n, 0, 1, vmin, vmax, vmin, vmax);
        plslabelfunc(labelTicks, logs);
        plcol0(kSlotInk);
        plbox("bc", 0, 0, "bcmstvo", a.step(), 0);
    } else {
        pl.frame(box, vmin, vmax, 0, 1);
        drawImage(g, n, 1, vmin, vmax, 0, 1, vmin, vmax);
        plslabelfunc(labelTicks, logs);
        plcol0(kSlotInk);
        plbox("bcnsto", a.step(), 0, "bc", 0, 0);
    }
    plslabelfunc(nullptr, nullptr);
}

// ---------------------------------------------------------------------------
// Line plots.

constexpr int kLegendRow = 18, kLegendSample = 34, kLegendPad = 6;
// Dash patterns (PLplot line styles) and markers by series index: the first
// series solid with filled dots, later ones dashed with open markers, so one
// drawn over an identical one leaves both visible.
constexpr PLINT kLineStyles[4] = {1, 2, 3, 4};
const char* const kMarkers[6] = {"●", "□", "△", "◇", "▽", "○"};
constexpr size_t kMaxMarkedPoints = 16;

bool samePoints(const PlotSeries& a, const PlotSeries& b) {
    if (a.x.size() != b.x.size() || a.y.size() != b.y.size() || a.bars != b.bars) return false;
    auto close = [](double u, double v) {
        return u == v || std::abs(u - v) <= 1e-9 * std::max(std::abs(u), std::abs(v));
    };
    for (size_t i = 0; i < a.x.size(); ++i)
        if (!close(a.x[i], b.x[i])) return false;
    for (size_t i = 0; i < a.y.size(); ++i)
        if (!close(a.y[i], b.y[i])) return false;
    return true;
}

struct LegendEntry {
    size_t series;
    std::string text;
};

std::vector<LegendEntry> legendEntries(const std::vector<PlotSeries>& series) {
    std::vector<LegendEntry> out;
    const std::vector<std::string> labels = seriesLabels(series);
    for (size_t i = 0; i < series.size(); ++i)
        if (!labels[i].empty()) out.push_back({i, labels[i]});
    return out;
}

bool plotted(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }
double world(double v, bool log) { return log ? std::log10(v) : v; }

void drawSeries(const PlotSeries& s, size_t index, const LinePlotOptions& o, double yBase) {
    const PLINT slot = kSlotSeries + PLINT(index);
    setSlot(slot, toRgb8(s.colour));
    plcol0(slot);
    const size_t n = std::min(s.x.size(), s.y.size());
    if (s.bars) {
        const double step = n > 1 ? (s.x[1] - s.x[0]) : 1.0;
        for (size_t i = 0; i < n; ++i) {
            if (!plotted(s.y[i], o.logY)) continue;
            const double a = s.x[i] - 0.5 * step, b = s.x[i] + 0.5 * step;
            if (o.logX && !(a > 0)) continue;
            PLFLT xs[4] = {world(a, o.logX), world(b, o.logX), world(b, o.logX), world(a, o.logX)};
            PLFLT ys[4] = {yBase, yBase, world(s.y[i], o.logY), world(s.y[i], o.logY)};
            plfill(4, xs, ys);
        }
        return;
    }
    std::vector<PLFLT> xs, ys;
    for (size_t i = 0; i < n; ++i)
        if (plotted(s.x[i], o.logX) && plotted(s.y[i], o.logY)) {
            xs.push_back(world(s.x[i], o.logX));
            ys.push_back(world(s.y[i], o.logY));
        }
    plwidth(2);
    pllsty(kLineStyles[index % 4]);
    if (xs.size() > 1) plline(PLINT(xs.size()), xs.data(), ys.data());
    pllsty(1);
    plwidth(1);
    if (!xs.empty() && xs.size() <= kMaxMarkedPoints)
        plstring(PLINT(xs.size()), xs.data(), ys.data(), kMarkers[index % 6]);
}

void drawLegend(const Plplot& pl, const PixelBox& box, const std::vector<LegendEntry>& entries,
                const std::vector<PlotSeries>& series) {
    pl.rect(box, kSlotWhite, true);
    pl.rect(box, kSlotInk, false);
    for (size_t e = 0; e < entries.size(); ++e) {
        const PlotSeries& s = series[entries[e].series];
        const size_t index = entries[e].series;
        const double cy = box.y0 + kLegendPad + (double(e) + 0.5) * kLegendRow;
        const double x0 = box.x0 + kLegendPad, x1 = x0 + kLegendSample;
        pl.pixels();
        plcol0(kSlotSeries + PLINT(index));
        if (s.bars) {
            pl.rect({int(x0 + 8), int(cy - 5), int(x1 - 8), int(cy + 5)}, kSlotSeries + PLINT(index), true);
        } else {
            PLFLT xs[2] = {x0, x1}, ys[2] = {pl.row(cy), pl.row(cy)};
            plwidth(2);
            pllsty(kLineStyles[index % 4]);
            plline(2, xs, ys);
            pllsty(1);
            plwidth(1);
            if (std::min(s.x.size(), s.y.size()) <= kMaxMarkedPoints) {
                PLFLT mx = 0.5 * (x0 + x1), my = pl.row(cy);
                plstring(1, &mx, &my, kMarkers[index % 6]);
            }
        }
        plcol0(kSlotInk);
        pl.text(x1 + kLegendPad, cy, entries[e].text, 0.0);
    }
}

}  // namespace

std::vector<std::string> seriesLabels(const std::vector<PlotSeries>& series) {
    std::vector<std::string> out;
    for (size_t i = 0; i < series.size(); ++i) {
        std::string t = series[i].name;
        if (!t.empty())
            for (size_t j = 0; j < i; ++j)
                if (samePoints(series[i], series[j])) {
                    t += " (same values as " +
                         (series[j].name.empty() ? "series " + std::to_string(j + 1) : series[j].name) + ")";
                    break;
                }
        out.push_back(std::move(t));
    }
    return out;
}

Image heatmapPlot(const Image& values, const HeatmapOptions& o, PlotLayout* layout) {
    if (values.channels() != 1 || values.empty()) throw std::invalid_argument("heatmapPlot: 1-channel values needed");
    const int w = values.width(), h = values.height();
    const int cell = o.cell > 0 ? o.cell : std::max(1, 512 / std::max(w, h));
    const int pw = w * cell, ph = h * cell;
    const std::lock_guard lock(plotMutex());
    const Axis xa{o.xMin, o.xMax, false, pw, 60}, ya{o.yMin, o.yMax, false, ph, 30}, va{o.vmin, o.vmax, false, ph, 30};
    const Margins m = axesMargins(ya, o.title, o.yLabel);
    const int barGap = 16, barW = 16;
    const int barLabels = 8 + va.labelWidth();
    int width = m.left + pw + barGap + barW + barLabels + 10;
    width = std::max(width, textSize(o.title, kTitlePx)[0] + 20);
    const int height = m.top + ph + m.bottom;
    const PixelBox area{m.left, m.top, m.left + pw, m.top + ph};
    const PixelBox bar{area.x1 + barGap, area.y0, area.x1 + barGap + barW, area.y1};

    Canvas canvas(width, height);
    {
        Plplot pl(canvas);
        setPalette(o.palette);
        pl.rect(area, kSlotMissing, true);  // shows through where a value is not finite
        // PLplot's image rows go up from y0; values with non-finite entries
        // are pushed outside [vmin, vmax], which plimagefr leaves undrawn.
        std::vector<double> data(size_t(w) * size_t(h));
        const double outside = o.vmax + 1.0 + std::abs(o.vmax - o.vmin);
        for (int x = 0; x < w; ++x)
            for (int y = 0; y < h; ++y) {
                const double v = values.at(x, y);
                data[size_t(x) * size_t(h) + size_t(y)] = std::isfinite(v) ? std::clamp(v, o.vmin, o.vmax) : outside;
            }
        // yUp: row 0 at the bottom, so the world window runs yMin (bottom) to
        // yMax; otherwise the window is flipped and row 0 lands at the top.
        const double wy0 = o.yUp ? o.yMin : o.yMax, wy1 = o.yUp ? o.yMax : o.yMin;
        pl.frame(area, o.xMin, o.xMax, wy0, wy1);
        drawImage(data, w, h, o.xMin, o.xMax, o.yMin, o.yMax, o.vmin, o.vmax);
        drawAxes(pl, area, xa, Axis{wy0, wy1, false, ph, 30}, o.xLabel, o.yLabel, false);
        drawColourBar(pl, bar, o.vmin, o.vmax, true);
        pl.text(width / 2.0, m.top / 2.0, o.title, 0.5, kTitlePx);
    }
    if (layout) *layout = {area, {bar.x0, bar.y0, bar.x1 + barLabels, bar.y1}};
    return canvas.image();
}

Image colourise(const Image& values, double vmin, double vmax, HeatPalette palette) {
    Image out(values.width(), values.height(), 3, Image::Uninitialized{});
    const auto lut = paletteLut(palette);
    const double span = vmax - vmin;
    for (int y = 0; y < values.height(); ++y)
        for (int x = 0; x < values.width(); ++x) {
            const double t = span > 0 ? (values.at(x, y) - vmin) / span : 0.5;
            const Rgb& c = lut[size_t(std::clamp(int(std::lround(255 * t)), 0, 255))];
            for (int k = 0; k < 3; ++k) out.at(x, y, k) = float(c[size_t(k)]) / 255.0f;
        }
    return out;
}

Image colourLegend(double vmin, double vmax, HeatPalette palette, const std::string& title, int width) {
    const std::lock_guard lock(plotMutex());
    width = std::max(width, textSize(title, kFontPx)[0] + 20);
    const int side = 24, top = int(kFontPx) * 2 + 4, barH = 14;
    const PixelBox bar{side, top, width - side, top + barH};
    Canvas canvas(width, top + barH + int(2.2 * kFontPx));
    {
        Plplot pl(canvas);
        setPalette(palette);
        drawColourBar(pl, bar, vmin, vmax, false);
        pl.text(width / 2.0, top / 2.0, title);
    }
    return canvas.image();
}

std::array<float, 3> seriesColour(size_t i) {
    // Tableau 10: distinct in hue and lightness, and readable on white.
    static constexpr std::array<float, 3> palette[10] = {
        {0.122f, 0.467f, 0.706f}, {1.000f, 0.498f, 0.055f}, {0.173f, 0.627f, 0.173f}, {0.839f, 0.153f, 0.157f},
        {0.580f, 0.404f, 0.741f}, {0.549f, 0.337f, 0.294f}, {0.890f, 0.467f, 0.761f}, {0.498f, 0.498f, 0.498f},
        {0.737f, 0.741f, 0.133f}, {0.090f, 0.745f, 0.812f}};
    return palette[i % 10];
}

PlotRange linePlotRange(const std::vector<PlotSeries>& series, const LinePlotOptions& o) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& s : series)
        for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!plotted(s.x[i], o.logX) || !plotted(s.y[i], o.logY)) continue;
            x0 = std::min(x0, s.x[i]);
            x1 = std::max(x1, s.x[i]);
            y0 = std::min(y0, s.y[i]);
            y1 = std::max(y1, s.y[i]);
        }
    if (!std::isfinite(x0)) x0 = o.logX ? 1 : 0, x1 = o.logX ? 10 : 1, y0 = o.logY ? 1 : 0, y1 = o.logY ? 10 : 1;
    if (std::isfinite(o.xMin)) x0 = o.xMin;
    if (std::isfinite(o.xMax)) x1 = o.xMax;
    if (std::isfinite(o.yMin)) y0 = o.yMin;
    if (std::isfinite(o.yMax)) y1 = o.yMax;
    if (!std::isfinite(o.yMin) && !o.logY) y0 = std::min(y0, 0.0);
    if (!(x1 > x0)) x1 = o.logX ? x0 * 10 : x0 + 1.0;
    if (!(y1 > y0)) y1 = o.logY ? y0 * 10 : y0 + 1.0;
    if (!std::isfinite(o.yMax) && !o.logY) y1 += 0.05 * (y1 - y0);
    // Log axes span whole decades around the data, so PLplot labels at least one.
    if (o.logX && !std::isfinite(o.xMin) && std::floor(std::log10(x0)) == std::floor(std::log10(x1)))
        x0 = std::pow(10.0, std::floor(std::log10(x0)));
    if (o.logY && !std::isfinite(o.yMin)) y0 = std::pow(10.0, std::floor(std::log10(y0) + 1e-9));
    if (o.logY && !std::isfinite(o.yMax)) y1 = std::pow(10.0, std::ceil(std::log10(y1) - 1e-9));
    return {x0, x1, y0, y1};
}

std::string tickLabel(double v) { return number(v); }

Image linePlot(const std::vector<PlotSeries>& series, const LinePlotOptions& o, PlotLayout* layout) {
    const PlotRange r = linePlotRange(series, o);
    Axis xa{world(r.x0, o.logX), world(r.x1, o.logX), o.logX}, ya{world(r.y0, o.logY), world(r.y1, o.logY), o.logY};

    ya.tickSpacing = 30;
    ya.length = o.height - 70;  // about the frame's height, for the tick labels' width

    const std::lock_guard lock(plotMutex());
    const Margins m = axesMargins(ya, o.title, o.yLabel);
    const int pw = std::max(40, o.width - m.left - m.right), ph = std::max(40, o.height - m.top - m.bottom);
    xa.length = pw;
    ya.length = ph;
    const PixelBox area{m.left, m.top, m.left + pw, m.top + ph};
    // The legend sits right of the axes, sized to its text: the image grows
    // for it instead of the legend covering curves or leaving the image.
    const auto entries = legendEntries(series);
    PixelBox legend;
    int width = area.x1 + m.right, height = area.y1 + m.bottom;
    if (!entries.empty()) {
        int textW = 0;
        for (const auto& e : entries) textW = std::max(textW, textSize(e.text, kFontPx)[0]);
        legend.x0 = area.x1 + m.right;
        legend.y0 = area.y0;
        legend.x1 = legend.x0 + 3 * kLegendPad + kLegendSample + textW;
        legend.y1 = legend.y0 + 2 * kLegendPad + kLegendRow * int(entries.size());
        width = legend.x1 + 10;
        height = std::max(height, legend.y1 + 10);
    }
    width = std::max(width, textSize(o.title, kTitlePx)[0] + 20);

    Canvas canvas(width, height);
    {
        Plplot pl(canvas, int(series.size()));
        pl.frame(area, xa.lo, xa.hi, ya.lo, ya.hi);
        plcol0(kSlotBand);
        for (const auto& b : o.bands) {
            const double a = std::clamp(world(b[0], o.logX), xa.lo, xa.hi);
            const double c = std::clamp(world(b[1], o.logX), xa.lo, xa.hi);
            PLFLT xs[4] = {a, c, c, a}, ys[4] = {ya.lo, ya.lo, ya.hi, ya.hi};
            plfill(4, xs, ys);
        }
        plcol0(kSlotGrid);
        plbox(xa.options("g").c_str(), xa.step(), 0, ya.options("g").c_str(), ya.step(), 0);
        const double yBase = o.logY ? ya.lo : std::clamp(0.0, ya.lo, ya.hi);
        for (size_t i = 0; i < series.size(); ++i) {
            pl.frame(area, xa.lo, xa.hi, ya.lo, ya.hi);
            drawSeries(series[i], i, o, yBase);
        }
        drawAxes(pl, area, xa, ya, o.xLabel, o.yLabel, false);
        if (!entries.empty()) drawLegend(pl, legend, entries, series);
        pl.text(width / 2.0, m.top / 2.0, o.title, 0.5, kTitlePx);
    }
    if (layout) *layout = {area, legend};
    return canvas.image();
}

std::vector<double> histogram(const Image& image, int bins, double lo, double hi) {
    std::vector<double> h(static_cast<size_t>(bins), 0.0);
    const size_t n = image.pixelCount();
    for (size_t i = 0; i < n; ++i) {
        const double v = image.data()[i * size_t(image.channels())];
        const int b = std::clamp(int((v - lo) / (hi - lo) * bins), 0, bins - 1);
        h[size_t(b)] += 1.0;
    }
    for (double& v : h) v /= double(std::max<size_t>(n, 1));
    return h;
}

Image sheet(const std::vector<std::vector<Image>>& rows, const std::vector<std::vector<std::string>>& captions) {
    const int pad = 10, captionGap = 4;
    auto captionOf = [&](size_t r, size_t c) -> const std::string& {
        static const std::string none;
        return r < captions.size() && c < captions[r].size() ? captions[r][c] : none;
    };
    const std::lock_guard lock(plotMutex());
    // Each column is as wide as its image (at least kSheetMinCaptionWidth when
    // captioned); each row as tall as its tallest image plus its tallest
    // wrapped caption.
    std::vector<std::vector<int>> colW(rows.size());
    std::vector<int> rowH(rows.size(), 0), capH(rows.size(), 0);
    int width = pad, height = pad;
    for (size_t r = 0; r < rows.size(); ++r) {
        int w = pad;
        for (size_t c = 0; c < rows[r].size(); ++c) {
            const std::string& cap = captionOf(r, c);
            const int cw = cap.empty() ? rows[r][c].width() : std::max(rows[r][c].width(), kSheetMinCaptionWidth);
            colW[r].push_back(cw);
            if (!cap.empty()) capH[r] = std::max(capH[r], textSize(cap, kFontPx, cw)[1] + captionGap);
            rowH[r] = std::max(rowH[r], rows[r][c].height());
            w += cw + pad;
        }
        width = std::max(width, w);
        height += rowH[r] + capH[r] + pad;
    }
    Canvas canvas(width, height);
    cairo_set_source_rgb(canvas.cr, kInk[0] / 255.0, kInk[1] / 255.0, kInk[2] / 255.0);
    int y = pad;
    for (size_t r = 0; r < rows.size(); ++r) {
        int x = pad;
        for (size_t c = 0; c < rows[r].size(); ++c) {
            const std::string& cap = captionOf(r, c);
            if (!cap.empty()) {
                const Layout text(canvas.cr, cap, kFontPx, colW[r][c]);
                cairo_move_to(canvas.cr, x, y + rows[r][c].height() + captionGap);
                pango_cairo_show_layout(canvas.cr, text.layout);
            }
            x += colW[r][c] + pad;
        }
        y += rowH[r] + capH[r] + pad;
    }
    Image out = canvas.image();
    y = pad;
    for (size_t r = 0; r < rows.size(); ++r) {
        int x = pad;
        for (size_t c = 0; c < rows[r].size(); ++c) {
            const Image& im = rows[r][c];
            paste(out, stochtex::toRgb(im), x + (colW[r][c] - im.width()) / 2, y);
            x += colW[r][c] + pad;
        }
        y += rowH[r] + capH[r] + pad;
    }
    return out;
}

}  // namespace stochtex
