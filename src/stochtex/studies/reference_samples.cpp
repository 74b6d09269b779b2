#include "stochtex/studies/reference_samples.h"

#include <algorithm>
#include <cmath>

#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/part_cache.h"

namespace stochtex {

namespace {

// The probe pixels' colours under `options`, row-major.
std::vector<Rgb> probeColours(const GraphPattern& graph, const FilterOptions& options, const Camera& camera,
                              GraphMoments moments, int probe, PartCache* parts) {
    const FilteredGraph filtered(graph, options, moments, parts);
    const int w = graph.exampleSize();
    const bool shadesLight = graph.shadesLight();
    std::vector<Rgb> out(size_t(probe) * size_t(probe));
    parallelRows(probe, [&](int y0, int y1) {
        for (int i = y0; i < y1; ++i)
            for (int k = 0; k < probe; ++k) {
                // An even grid of the image's own pixels (their centres, as render shades them).
                const int px = int((k + 0.5) * camera.view.width / probe);
                const int py = int((i + 0.5) * camera.view.height / probe);
                double u = 0, v = 0;
                Jacobian j;
                const bool onPlane = camera.footprint(px, py, w, u, v, j);
                const GraphPattern::Direction eye =
                    shadesLight ? camera.viewDirection(px, py) : GraphPattern::kFromAbove;
                out[size_t(i) * size_t(probe) + size_t(k)] = filtered.shade(onPlane, u, v, j, eye);
            }
    });
    return out;
}

double meanDistance(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        double d2 = 0;
        for (size_t k = 0; k < 3; ++k) d2 += double(a[i][k] - b[i][k]) * double(a[i][k] - b[i][k]);
        sum += std::sqrt(d2);
    }
    return a.empty() ? 0.0 : sum / double(a.size());
}

}  // namespace

FilterOptions atConvergedSamples(const GraphPattern& graph, const FilterOptions& options, const Camera& camera,
                                 double tolerance, int& perAxis, double& change, PartCache* parts) {
    const ConvergedSamples chosen =
        convergedSamples(graph, options, camera, tolerance, GraphMoments::Matched, kConvergenceProbe, parts);
    perAxis = chosen.perAxis;
    change = chosen.change;
    return withSamples(options, chosen.perAxis);
}

void validateReferenceTolerance(double tolerance) {
    if (!(tolerance > 0 && tolerance <= 0.1))
        throw InputError::parameter("referenceTolerance", "must be in (0, 0.1], got " + formatValue(tolerance));
}

ConvergedSamples convergedSamples(const GraphPattern& graph, FilterOptions options, const Camera& camera,
                                  double tolerance, GraphMoments moments, int probe, PartCache* parts) {
    if (options.source != StatisticsSource::Reference && options.source != StatisticsSource::Exact)
        throw InputError::parameter("source", "converged samples apply to the reference and exact sources only");
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw InputError::parameter("tolerance", "must be a positive number");
    if (probe < 1 || probe > 256) throw InputError::parameter("probe", "must be in [1, 256], got " + std::to_string(probe));
    validateFilterOptions(options);
    const int cap = options.referenceMaxSamples, first = std::min(8, cap);
    auto at = [&](int n) { return probeColours(graph, withSamples(options, n), camera, moments, probe, parts); };
    ConvergedSamples result;
    std::vector<Rgb> coarse = at(first);
    for (int n = first;; n = std::min(2 * n, cap)) {
        // The doubled count of the cap is measured only, never rendered.
        const int twice = std::min(2 * n, kMaxSamplesPerAxis);
        const std::vector<Rgb> fine = at(twice);
        result.perAxis = n;
        result.change = meanDistance(coarse, fine);
        result.converged = twice > n && result.change < tolerance;
        if (result.converged || n >= cap) return result;
        coarse = 2 * n <= cap ? fine : at(cap);
    }
}

}  // namespace stochtex
