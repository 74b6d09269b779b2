#include <gtest/gtest.h>

#include <cmath>

#include "stochtex/analysis/zoom_stability.h"
#include "stochtex/core/hash.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/pattern/presets.h"

using namespace stochtex;

namespace {
// A smooth texture-space function seen at a zoom about the image centre.
Image smoothFrame(int n, double scale) {
    Image img(n, n, 1);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double tx = (x + 0.5 - 0.5 * n) * scale, ty = (y + 0.5 - 0.5 * n) * scale;
            img.at(x, y) = float(0.5 + 0.25 * std::sin(tx / 9.0) + 0.2 * std::cos(ty / 7.0));
        }
    return img;
}
}  // namespace

TEST(ZoomStability, CompensationCancelsThePureZoom) {
    const double d = compensatedZoomDifference(smoothFrame(64, 1.0), 1.0, smoothFrame(64, 1.1), 1.1);
    EXPECT_LT(d, 0.005);
    // Without compensation (claiming the same scale) the frames differ a lot.
    EXPECT_GT(compensatedZoomDifference(smoothFrame(64, 1.0), 1.0, smoothFrame(64, 1.1), 1.0), 0.03);
    Image noise(64, 64, 1);
    for (int i = 0; i < 64 * 64; ++i) noise.data()[size_t(i)] = unitFloat(pcg3d({uint32_t(i), 1, 2}).x);
    EXPECT_GT(compensatedZoomDifference(smoothFrame(64, 1.0), 1.0, noise, 1.1), 0.15);
}

TEST(ZoomStability, FilteringRemovesMostFlicker) {
    const GraphPattern p = GraphPattern::build(loadPreset("marble"));
    auto run = [&](const char* filter) {
        const FilteredGraph f(p, FilterOptions{}.use(parseFilter(filter)));
        return measureZoomStability(
                   [&](double s) {
                       Camera c;
                       c.view.width = c.view.height = 48;
                       c.view.scale = s;
                       c.view.offsetU = c.view.offsetV = -24 * s;
                       return f.render(c);
                   },
                   12, 1.0, 64.0)
            .mean;
    };
    const double none = run("none"), smooth = run("smooth"), paper = run("paper");
    EXPECT_LT(smooth, 0.4 * none);
    EXPECT_LT(paper, 0.4 * none);
}
