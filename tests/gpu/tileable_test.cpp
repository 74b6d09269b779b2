// Tileable renders (pattern/tileable.h): the field itself periodic over the
// view, so the image wraps without a seam, on the CPU and the GPU alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/noise/tiling_blending_lanes.h"
#include "stochtex/pattern/cpu_renderer.h"
#include "stochtex/pattern/part_cache.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/pattern/tileable.h"
#include "test_util.h"

namespace stochtex {
namespace {

Image renderCpu(const PatternSpec& spec, const FilterOptions& o, const View& view) {
    Camera c;
    c.view = view;
    return makeCpuRenderer(spec, o)->render(c);
}

// Mean |Δ| over a pair of columns (x0, x1) or, transposed, rows.
double columnDifference(const Image& img, int x0, int x1) {
    double d = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int c = 0; c < 3; ++c) d += std::abs(img.at(x0, y, c) - img.at(x1, y, c));
    return d / (3.0 * img.height());
}
double rowDifference(const Image& img, int y0, int y1) {
    double d = 0;
    for (int x = 0; x < img.width(); ++x)
        for (int c = 0; c < 3; ++c) d += std::abs(img.at(x, y0, c) - img.at(x, y1, c));
    return d / (3.0 * img.width());
}

// The wrap-around difference (last column against the first; last row
// against the first) in units of the interior neighbours' spread: (wrap −
// mean) / std of the differences of neighbouring interior columns (rows).
struct Seam {
    double columnZ, rowZ, columnRatio, rowRatio;
};
Seam seamOf(const Image& img) {
    const auto stats = [](const std::vector<double>& d, double wrap) {
        double mean = 0, var = 0;
        for (const double v : d) mean += v / double(d.size());
        for (const double v : d) var += (v - mean) * (v - mean) / double(d.size());
        return std::pair{(wrap - mean) / std::sqrt(var), wrap / mean};
    };
    std::vector<double> columns, rows;
    for (int x = 0; x + 1 < img.width(); ++x) columns.push_back(columnDifference(img, x, x + 1));
    for (int y = 0; y + 1 < img.height(); ++y) rows.push_back(rowDifference(img, y, y + 1));
    const auto [cz, cr] = stats(columns, columnDifference(img, img.width() - 1, 0));
    const auto [rz, rr] = stats(rows, rowDifference(img, img.height() - 1, 0));
    return {cz, rz, cr, rr};
}

// A tileable bake wraps like its interior: the difference between its last
// and first column (row) is within 3 standard deviations of the interior
// neighbours' differences, unfiltered and filtered, for a plain pattern, a
// quadrature pair and a lean normal map; the same view without --tileable
// is measured too (its wrap differs like unrelated columns, well outside).
// Its field is periodic: shifted by one period, the render is the same.
TEST(Tileable, WrapsWithoutASeamAndIsPeriodic) {
    struct Case {
        const char* preset;
        const char* filter;
        ResponseKind response;
    };
    for (const Case& c : {Case{"camouflage", "none", ResponseKind::PrefilteredColormap},
                          Case{"camouflage", "smooth", ResponseKind::PrefilteredColormap},
                          Case{"phasor-stripes", "paper", ResponseKind::PrefilteredColormap},
                          Case{"lean-ridges", "smooth", ResponseKind::Lean}}) {
        SCOPED_TRACE(std::string(c.preset) + " " + c.filter);
        FilterOptions o;
        o.use(parseFilter(c.filter));
        o.response.kind = c.response;
        PatternSpec spec = loadPreset(c.preset);
        View view;
        view.width = view.height = 160;
        view.scale = 2.9;  // 1.8 periods of 256 texels: made 2
        view.offsetU = 37;
        view.offsetV = -11;
        const Image plain = renderCpu(spec, o, view);
        const TilePeriod t = makeTileable(spec, o.response, view);
        EXPECT_EQ(t.periodsU, 2);
        EXPECT_EQ(t.periodsV, 2);
        EXPECT_DOUBLE_EQ(view.scale, 2.0 * t.exampleSize / 160.0);
        const Image tiled = renderCpu(spec, o, view);
        const Seam s = seamOf(tiled), p = seamOf(plain);
        std::printf(
            "[ info ] %s %s: wrap-around difference %.2f (columns) and %.2f (rows) interior standard "
            "deviations from their mean (%.2fx, %.2fx the mean); not tileable: %.2f, %.2f (%.2fx, %.2fx); "
            "grid stretched %.4fx along u\n",
            c.preset, c.filter, s.columnZ, s.rowZ, s.columnRatio, s.rowRatio, p.columnZ, p.rowZ, p.columnRatio,
            p.rowRatio, t.stretch);
        EXPECT_LT(s.columnZ, 3.0);
        EXPECT_LT(s.rowZ, 3.0);
        EXPECT_GT(std::max(p.columnZ, p.rowZ), 3.0);  // the measure sees the seam of a plain render
        // One period further along u and v: the same field.
        View shifted = view;
        shifted.offsetU += t.periodsU * t.exampleSize;
        shifted.offsetV -= t.periodsV * t.exampleSize;
        const Image again = renderCpu(spec, o, shifted);
        double largest = 0;
        for (size_t i = 0; i < tiled.data().size(); ++i)
            largest = std::max(largest, double(std::abs(tiled.data()[i] - again.data()[i])));
        EXPECT_LT(largest, 2e-4);
    }
}

// makeTileable builds the program to learn its period: with a PartCache,
// the render that follows takes its examples from there (no example
// synthesised twice) and renders what a render without the cache does, bit
// for bit.
TEST(Tileable, ThePeriodsProgramLendsItsPartsToTheRender) {
    FilterOptions o;
    o.use(parseFilter("smooth"));
    PatternSpec spec = loadPreset("camouflage");
    View view;
    view.width = view.height = 64;
    view.scale = 7.0;
    PartCache parts;
    makeTileable(spec, o.response, view, &parts);
    const PartCache::Builds period = parts.builds();
    EXPECT_EQ(period.fields, 2);  // camouflage's two noises
    Camera camera;
    camera.view = view;
    const Image cached = makeCpuRenderer(spec, o, &parts)->render(camera);
    EXPECT_EQ(parts.builds().fields, period.fields);
    EXPECT_EQ(parts.builds().colormaps, period.colormaps);
    EXPECT_GT(parts.builds().estimators, period.estimators);  // the filtered render's own: the period built none
    EXPECT_EQ(cached.data(), renderCpu(spec, o, view).data());
}

// The GPU renders the periodic grid the CPU does (the kernel's
// periodicVertex on both): mean |Δ| within the CPU/GPU tolerance.
TEST(Tileable, GpuRendersTheCpusPeriodicPattern) {
    for (const char* filter : {"none", "smooth"}) {
        FilterOptions o;
        o.use(parseFilter(filter));
        PatternSpec spec = loadPreset("camouflage");
        View view;
        view.width = view.height = 128;
        view.scale = 4.0;
        makeTileable(spec, o.response, view);
        const Image cpu = renderCpu(spec, o, view);
        const Image gpu = makeGpuView(spec, test::glContext(), o)->render(view);
        double mean = 0;
        for (size_t i = 0; i < cpu.data().size(); ++i) mean += std::abs(cpu.data()[i] - gpu.data()[i]);
        mean /= double(cpu.data().size());
        std::printf("[ info ] tileable camouflage (%s): mean |CPU - GPU| %.2e\n", filter, mean);
        EXPECT_LT(mean, 2e-4) << filter;
        EXPECT_LT(seamOf(gpu).columnZ, 3.0) << filter;
    }
}

// What cannot tile is refused by name: a view whose height covers no whole
// number of periods once its width does, a graph that transforms a leaf's
// uv; the SIMD grid refuses a periodic grid (the lanes hash the plane's
// vertices: the renderers take the scalar kernel for it).
TEST(Tileable, RefusesWhatCannotTile) {
    PatternSpec spec = loadPreset("camouflage");
    View view;
    view.width = 256;
    view.height = 100;
    view.scale = 1.0;
    EXPECT_EQ(test::inputErrorOf([&] { makeTileable(spec, ResponseOptions{}, view); }).parameter(), "size");
    PatternSpec bad = loadPreset("camouflage");
    bad.gridPeriods = {1, 0};
    EXPECT_EQ(test::inputErrorOf([&] { GraphPattern::build(bad); }).parameter(), "gridPeriods");
    GridRowLanes lanes;
    EXPECT_THROW(lanes.compute(0, 1, 1.0 / 256, 0.5, 8, GridLayout::periodic(kDefaultGridDensity, 1, 1)),
                 std::logic_error);
}

// The PBR maps of a normal map (the surface op: bake-image --pbr): the
// normal map leans against the height map's gradient (R − ½ with −∂h/∂x,
// G − ½ with ∂h/∂row: OpenGL's y is up the image, rows run down it), with
// correlations above 0.8 unfiltered; the roughness is the base lobe's
// (√m) unfiltered and grows with the footprint (the slopes' variance joins
// the lobe); the height map is the height example's values (mean ½); and
// the GPU renders each map the CPU does.
TEST(PbrMaps, NormalFollowsTheHeightAndRoughnessGrowsWithTheFootprint) {
    const PatternSpec spec = loadPreset("lean-ridges");
    const auto render = [&](ResponseKind kind, const char* filter, double scale) {
        FilterOptions o;
        o.use(parseFilter(filter));
        o.response.kind = kind;
        View view;
        view.width = view.height = 128;
        view.scale = scale;
        return renderCpu(spec, o, view);
    };
    const Image normal = render(ResponseKind::Normal, "none", 1.0), height = render(ResponseKind::Height, "none", 1.0);
    const auto correlation = [](const std::vector<double>& a, const std::vector<double>& b) {
        double ma = 0, mb = 0, ab = 0, aa = 0, bb = 0;
        for (size_t i = 0; i < a.size(); ++i) ma += a[i] / double(a.size()), mb += b[i] / double(b.size());
        for (size_t i = 0; i < a.size(); ++i)
            ab += (a[i] - ma) * (b[i] - mb), aa += (a[i] - ma) * (a[i] - ma), bb += (b[i] - mb) * (b[i] - mb);
        return ab / std::sqrt(aa * bb);
    };
    std::vector<double> red, minusDx, green, dRow;
    double heightMean = 0;
    for (int y = 1; y + 1 < 128; ++y)
        for (int x = 1; x + 1 < 128; ++x) {
            red.push_back(normal.at(x, y, 0) - 0.5);
            minusDx.push_back(-(height.at(x + 1, y, 0) - height.at(x - 1, y, 0)));
            green.push_back(normal.at(x, y, 1) - 0.5);
            dRow.push_back(height.at(x, y + 1, 0) - height.at(x, y - 1, 0));
            heightMean += height.at(x, y, 0) / (126.0 * 126.0);
        }
    const double rx = correlation(red, minusDx), gy = correlation(green, dRow);
    std::printf(
        "[ info ] normal map against the height's gradient: corr(R, -dh/dx) %.3f, corr(G, dh/drow) %.3f; "
        "height mean %.3f\n",
        rx, gy, heightMean);
    EXPECT_GT(rx, 0.8);
    EXPECT_GT(gy, 0.8);
    EXPECT_NEAR(heightMean, 0.5, 0.05);
    // Roughness: √m unfiltered (m = 0.08, the file's), then growing with the footprint.
    const auto meanOf = [](const Image& img) {
        double m = 0;
        for (const float v : img.data()) m += v / double(img.data().size());
        return m;
    };
    const double r1 = meanOf(render(ResponseKind::Roughness, "none", 1.0)),
                 r2 = meanOf(render(ResponseKind::Roughness, "smooth", 2.0)),
                 r8 = meanOf(render(ResponseKind::Roughness, "smooth", 8.0));
    std::printf("[ info ] roughness: %.4f unfiltered, %.4f at 2 texels per pixel, %.4f at 8\n", r1, r2, r8);
    EXPECT_NEAR(r1, std::sqrt(0.08), 1e-4);
    EXPECT_GT(r2, r1 + 0.01);
    EXPECT_GT(r8, r2 + 0.01);
    // On the GPU alike, each map, filtered.
    for (const ResponseKind kind : {ResponseKind::Normal, ResponseKind::Roughness, ResponseKind::Height}) {
        FilterOptions o;
        o.use(parseFilter("smooth"));
        o.response.kind = kind;
        View view;
        view.width = view.height = 96;
        view.scale = 3.0;
        const Image cpu = renderCpu(spec, o, view), gpu = makeGpuView(spec, test::glContext(), o)->render(view);
        double mean = 0;
        for (size_t i = 0; i < cpu.data().size(); ++i) mean += std::abs(cpu.data()[i] - gpu.data()[i]);
        mean /= double(cpu.data().size());
        EXPECT_LT(mean, 1e-4) << enumName(kResponseKindNames, kind);
    }
}

}  // namespace
}  // namespace stochtex
