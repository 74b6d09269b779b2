// Not built by CMake: a measurement quoted in docs/RESULTS.md (Table 1,
// "Our μ̂ errors are smaller"). Build against a Release build folder:
//   g++ -std=c++20 -O2 -Isrc -I/usr/include/opencv4 scripts/experiments/table1_registration.cpp \
//     -Wl,--start-group build/src/stochtex/*/libstochtex_*.a -Wl,--end-group -lopencv_video \
//     -lopencv_imgproc -lopencv_core -ltbb -lepoxy -lEGL -lpng16 \
//     $(pkg-config --libs plplot pangocairo cairo) -o /tmp/table1_registration
// Experiment: does a half-texel misregistration between the estimator and the
// reference reproduce the published μ̂ magnitudes?
#include <cstdio>
#include <cmath>
#include "stochtex/studies/paper.h"
#include "stochtex/pattern/graph_pattern.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/filter/footprint.h"
#include "stochtex/core/hash.h"
using namespace stochtex;
int main() {
    for (int which = 0; which < 2; ++which) {
        const GraphPattern p = GraphPattern::build(table1PatternSpec(which, 1));  // two leaves → colormap
        const TiledField& field = p.leafPairs().front();
        const int w = field.exampleSize();
        const FootprintEstimator est(field, false);
        for (int s : {2, 4, 8, 16, 32, 64}) {
            double e0 = 0, e5 = 0, e1 = 0, sig = 0; int n = 0;
            const double side = double(s) / w;
            const Jacobian j{side, 0.0, 0.0, side};
            for (int k = 0; k < 400; ++k) {
                const UInt3 h = pcg3d({uint32_t(k), uint32_t(s), 7u});
                const double u = 64.0 * unitFloat(h.x), v = 64.0 * unitFloat(h.y);
                const FootprintStats exact = bruteForceStats(field, u, v, j, 256);
                for (int a = 0; a < 2; ++a) sig += a == 0 ? exact.sigmaX() : exact.sigmaY();
                double shifts[3] = {0.0, 0.5, 1.0};
                double* acc[3] = {&e0, &e5, &e1};
                for (int t = 0; t < 3; ++t) {
                    const double d = shifts[t] / w;
                    const Footprint f = makeFootprint(u + d, v + d, j, w, est.maxLod(), 1);
                    const FootprintStats e = est.estimate(f, VarianceEstimator::Paper);
                    for (int a = 0; a < 2; ++a) *acc[t] += std::abs(e.mean[a] - exact.mean[a]);
                }
                n += 2;
            }
            std::printf("%s s=%3d  mu_err shift0 %.4f  shift0.5 %.4f  shift1 %.4f   mean sigma %.4f\n",
                        which ? "high" : "low ", s, e0 / n, e5 / n, e1 / n, sig / n);
        }
    }
}
