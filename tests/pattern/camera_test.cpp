// The cameras' uv and Jacobians: the plane's analytic J must be the
// derivative of its own uv mapping, and tilt 0 must be the zoom view.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/view_renderer.h"
#include "test_util.h"

namespace stochtex {
namespace {

Camera plane(double tilt, double fov, double scale) {
    Camera c;
    c.kind = Camera::Kind::Plane;
    c.tiltDeg = tilt;
    c.fovDeg = fov;
    c.view.width = 200;
    c.view.height = 150;
    c.view.scale = scale;
    c.view.offsetU = 37.5;
    c.view.offsetV = -12.0;
    return c;
}

// The trapezoid rule: uv(p + e) − uv(p) = ½(J(p) + J(p + e))·e + O(J''),
// below 1e-3 of |J| wherever J changes by less than 5% from one pixel to the
// next (near the horizon it changes faster than any step resolves).
TEST(Camera, PlaneJacobianIsTheDerivativeOfItsUv) {
    const int w = 256;
    int checked = 0;
    for (double tilt : {0.0, 35.0, 70.0})
        for (double fov : {40.0, 90.0}) {
            const Camera c = plane(tilt, fov, 2.5);
            for (int py = 0; py < c.view.height - 1; py += 7)
                for (int px = 0; px < c.view.width - 1; px += 11) {
                    double u0, v0, ux, vx, uy, vy;
                    Jacobian j0, jx, jy;
                    if (!c.footprint(px, py, w, u0, v0, j0) || !c.footprint(px + 1, py, w, ux, vx, jx) ||
                        !c.footprint(px, py + 1, w, uy, vy, jy))
                        continue;
                    if (std::abs(jy.dvdy - j0.dvdy) > 0.05 * j0.dvdy) continue;
                    const double norm =
                        std::sqrt(j0.dudx * j0.dudx + j0.dvdx * j0.dvdx + j0.dudy * j0.dudy + j0.dvdy * j0.dvdy);
                    EXPECT_NEAR(ux - u0, 0.5 * (j0.dudx + jx.dudx), 1e-3 * norm);
                    EXPECT_NEAR(vx - v0, 0.5 * (j0.dvdx + jx.dvdx), 1e-3 * norm);
                    EXPECT_NEAR(uy - u0, 0.5 * (j0.dudy + jy.dudy), 1e-3 * norm);
                    EXPECT_NEAR(vy - v0, 0.5 * (j0.dvdy + jy.dvdy), 1e-3 * norm);
                    ++checked;
                }
        }
    EXPECT_GT(checked, 1500);
}

TEST(Camera, PlaneAtTiltZeroIsTheZoomView) {
    Camera z = plane(0, 60, 3.0);
    z.kind = Camera::Kind::Zoom;
    const Camera p = plane(0, 60, 3.0);
    for (int py = 0; py < 150; py += 13)
        for (int px = 0; px < 200; px += 17) {
            double zu, zv, pu, pv;
            Jacobian zj, pj;
            ASSERT_TRUE(z.footprint(px, py, 128, zu, zv, zj));
            ASSERT_TRUE(p.footprint(px, py, 128, pu, pv, pj));
            // The plane's ray is the kernel's float planeRay (as on the GPU):
            // uv ≤ 5 periods within a few float ulps, J ≈ 0.023 to float precision.
            EXPECT_NEAR(pu, zu, 1e-6);
            EXPECT_NEAR(pv, zv, 1e-6);
            EXPECT_NEAR(pj.dudx, zj.dudx, 1e-8);
            EXPECT_NEAR(pj.dvdy, zj.dvdy, 1e-8);
            EXPECT_EQ(pj.dvdx, 0.0);
            EXPECT_NEAR(pj.dudy, 0.0, 1e-8);
        }
}

// Tilt 80° with a 60° field of view: the horizon is in the image, rows above
// it are sky, and footprints grow and stretch along v towards it.
TEST(Camera, PlaneSkyAboveTheHorizonAndStretchedFootprintsBelow) {
    const Camera c = plane(80, 60, 1.0);
    double u, v;
    Jacobian j;
    EXPECT_FALSE(c.footprint(100, 0, 256, u, v, j));
    ASSERT_TRUE(c.footprint(100, 149, 256, u, v, j));
    const double nearStretch = j.dvdy / j.dudx;
    int lastGround = 149;
    while (lastGround > 0 && c.footprint(100, lastGround - 1, 256, u, v, j)) --lastGround;
    EXPECT_GT(lastGround, 10);  // the horizon is well inside the image
    ASSERT_TRUE(c.footprint(100, lastGround + 5, 256, u, v, j));
    EXPECT_GT(j.dvdy / j.dudx, 10 * nearStretch);
}

// The tilt and the field of view are described once (ParamInfo): the range
// validateCamera checks is the entry's, and the entry names the CLI's flag.
TEST(Camera, TheParameterEntriesAreTheRangesChecked) {
    EXPECT_EQ(cameraTiltParam().name, "tiltDeg");
    EXPECT_EQ(cameraTiltParam().flag, "tilt");
    EXPECT_EQ(cameraFovParam().flag, "fov");
    EXPECT_EQ(cameraTiltParam().fallback.get<double>(), Camera{}.tiltDeg);
    for (const ParamInfo* p : {&cameraTiltParam(), &cameraFovParam()}) {
        const bool tilt = p == &cameraTiltParam();
        for (const double v :
             {p->min, p->max, std::nextafter(p->min, -1e9), std::nextafter(p->max, 1e9), std::nan("")}) {
            Camera c = plane(tilt ? v : 30, tilt ? 60 : v, 1.0);
            const bool inside = v >= p->min && v <= p->max;
            if (inside) {
                EXPECT_NO_THROW(validateCamera(c)) << p->name << " " << v;
            } else {
                const InputError e = test::inputErrorOf([&] { validateCamera(c); });
                EXPECT_EQ(e.parameter(), p->name) << v;
            }
        }
    }
    const InputError e = test::inputErrorOf([] { checkInteger(anisoParam(), 17); });
    EXPECT_EQ(e.parameter(), "aniso");
    EXPECT_STREQ(e.what(), "aniso must be in [1, 16], got 17");
    EXPECT_EQ(anisoParam().flag, "aniso");
    EXPECT_EQ(referenceMaxSamplesParam().flag, "reference-samples");
}

TEST(Camera, ErrorsNameTheParameterAndTheValue) {
    Camera c = plane(95, 60, 1.0);
    InputError e = test::inputErrorOf([&] { validateCamera(c); });
    EXPECT_EQ(e.parameter(), "tiltDeg");
    EXPECT_STREQ(e.what(), "tiltDeg must be in [0, 89] degrees, got 95");
    c = plane(30, 0.5, 1.0);
    e = test::inputErrorOf([&] { validateCamera(c); });
    EXPECT_EQ(e.parameter(), "fovDeg");
    EXPECT_STREQ(e.what(), "fovDeg must be in [1, 150] degrees, got 0.5");
    c = plane(30, 60, std::nan(""));
    e = test::inputErrorOf([&] { validateCamera(c); });
    EXPECT_EQ(e.parameter(), "scale");
    EXPECT_STREQ(e.what(), "scale must be in [1e-06, 1e+06], got nan");
    c = plane(30, 60, 1.0);
    c.view.width = 0;
    e = test::inputErrorOf([&] { validateCamera(c); });
    EXPECT_EQ(e.parameter(), "size");
    EXPECT_STREQ(e.what(), "size must be in [1, 16384] per side, got 0x150");
    c.view.width = c.view.height = 16384;
    e = test::inputErrorOf([&] { validateCamera(c); });
    EXPECT_STREQ(e.what(), "size must be at most 67108864 pixels, got 16384x16384");
}

// A view baked in bands holds one band: up to 65536 pixels a side, however
// many pixels in all, rendered in tiles of at most 16384 columns; a tile of
// a band is a render again.
TEST(Camera, ABakedViewIsCappedByItsBandsNotItsPixels) {
    View big{65536, 65536, 1.0};
    EXPECT_NO_THROW(validateView(big, ViewUse::BandedBake));
    EXPECT_STREQ(test::inputErrorOf([&] { validateView(big); }).what(),
                 "size must be in [1, 16384] per side, got 65536x65536");
    big.width = 65537;
    EXPECT_STREQ(test::inputErrorOf([&] { validateView(big, ViewUse::BandedBake); }).what(),
                 "size must be in [1, 65536] per side, got 65537x65536");
    Camera whole;
    whole.view = View{16384, 65536, 2.0, 3.0, -5.0};
    const Camera band = bandCamera(whole, 4096, 256);
    EXPECT_NO_THROW(validateCamera(band));
    EXPECT_EQ(band.view.height, 256);
    EXPECT_EQ(band.view.offsetV, -5.0 + 4096 * 2.0);  // rows 4096… of the whole view
    EXPECT_EQ(test::inputErrorOf([&] { bandCamera(whole, 65500, 256); }).parameter(), "rows");
    const Camera tile = columnCamera(whole, 100, 50);
    EXPECT_EQ(tile.view.width, 50);
    EXPECT_EQ(tile.view.offsetU, 3.0 + 100 * 2.0);
    EXPECT_EQ(test::inputErrorOf([&] { columnCamera(whole, 16380, 5); }).parameter(), "columns");
    whole.kind = Camera::Kind::Plane;
    EXPECT_EQ(test::inputErrorOf([&] { bandCamera(whole, 0, 1); }).parameter(), "camera");
    EXPECT_EQ(test::inputErrorOf([&] { columnCamera(whole, 0, 1); }).parameter(), "camera");
    // A band's rows: `band`, fewer where they would hold more than 16384 × 256 pixels.
    EXPECT_EQ(bandRows(300, 256), 256);
    EXPECT_EQ(bandRows(16384, 256), 256);
    EXPECT_EQ(bandRows(65536, 256), 64);
    EXPECT_EQ(bandRows(65536, 16), 16);
    EXPECT_EQ(bandRows(40000, 4096), 104);
    EXPECT_EQ(test::inputErrorOf([&] { bandRows(300, 0); }).parameter(), "band");

    // Bands in order, tiles side by side, each its pixels of the view: a
    // renderer that writes each pixel's absolute column and row (from its
    // camera's offset) gives them back in place, and no render is wider
    // than 16384.
    struct PixelRenderer : ViewRenderer {
        mutable int widest = 0;
        Image render(const Camera& c, const Progress&) const override {
            widest = std::max(widest, c.view.width);
            Image out(c.view.width, c.view.height, 3);
            for (int y = 0; y < c.view.height; ++y)
                for (int x = 0; x < c.view.width; ++x) {
                    out.at(x, y, 0) = float(c.view.offsetU / c.view.scale + x);
                    out.at(x, y, 1) = float(c.view.offsetV / c.view.scale + y);
                }
            return out;
        }
        int exampleSize() const override { return 64; }
    };
    for (const int width : {3, 40000}) {
        Camera view;
        view.view = View{width, 10, 2.0};
        PixelRenderer renderer;
        std::vector<int> heights;
        int y = 0, wrong = 0;
        renderInBands(renderer, view, 4, [&](const Image& rows) {
            heights.push_back(rows.height());
            ASSERT_EQ(rows.width(), width);
            for (int r = 0; r < rows.height(); ++r, ++y)
                for (int x = 0; x < width; ++x) wrong += rows.at(x, r, 0) != float(x) || rows.at(x, r, 1) != float(y);
        });
        EXPECT_EQ(heights, (std::vector<int>{4, 4, 2})) << width;
        EXPECT_EQ(wrong, 0) << width;
        EXPECT_EQ(renderer.widest, std::min(width, 16384));
    }
    Camera small;
    small.view = View{3, 10, 2.0};
    EXPECT_EQ(test::inputErrorOf([&] { renderInBands(PixelRenderer{}, small, 0, [](const Image&) {}); }).parameter(),
              "band");

    // The pattern's own view unless told otherwise.
    PatternSpec spec;
    spec.width = 300;
    spec.height = 200;
    spec.scale = 2;
    const View v = patternView(spec, std::vector<int>{64}, std::nullopt, std::vector<double>{1, 2});
    EXPECT_EQ(v.width, 64);
    EXPECT_EQ(v.height, 64);
    EXPECT_EQ(v.scale, 2.0);
    EXPECT_EQ(v.offsetV, 2.0);
    EXPECT_EQ(patternView(spec, {}, 0.5, {}).width, 300);
    EXPECT_EQ(test::inputErrorOf([&] { patternView(spec, {}, std::nullopt, std::vector<double>{1}); }).parameter(),
              "offset");
    EXPECT_EQ(test::inputErrorOf([&] {
                  patternView(spec, std::vector<int>{1, 2, 3}, std::nullopt, {});
              }).parameter(),
              "size");
}

}  // namespace
}  // namespace stochtex
