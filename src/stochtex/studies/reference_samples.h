#pragma once
// How many samples a brute-force image needs. The reference S̄ and the exact
// statistics average an n×n grid per pixel (pattern/filter_options.h); the
// figures compare filters against them, so n must make them accurate to
// well below the errors measured, and no larger: at 64² samples the
// references took nearly all of `reproduce all`'s time. The count is chosen
// by convergence, measured on a probe grid of the image's own pixels.
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

struct ConvergedSamples {
    int perAxis = 0;     // the samples per axis to render with
    double change = 0;   // mean ‖I_n − I_2n‖₂ (linear RGB) over the probe pixels at n = perAxis
    bool converged = false;  // change < tolerance (else perAxis is the cap)
};

// The options with exactly n×n samples per pixel for the brute-force sources.
inline FilterOptions withSamples(FilterOptions options, int n) {
    options.referenceMinSamples = options.referenceMaxSamples = n;
    return options;
}
// The probe grid's pixels per axis the studies measure convergence on.
constexpr int kConvergenceProbe = 32;
// The most samples per axis FilterOptions takes.
constexpr int kMaxSamplesPerAxis = 4096;

// The fewest samples per axis n ∈ {8, 16, 32, …} ∪ {options.referenceMaxSamples}
// (the cap; below 8, the cap alone) at which the image of `options` (source reference or exact)
// through `camera` moves by less than `tolerance` when n doubles, measured
// as the mean RGB distance over probe × probe pixels spread evenly over the
// image. Every pixel gets n×n samples, whatever its extent (a zoom's
// footprints are all alike; through a plane, the far pixels set n).
ConvergedSamples convergedSamples(const GraphPattern& graph, FilterOptions options, const Camera& camera,
                                  double tolerance, GraphMoments moments = GraphMoments::Matched,
                                  int probe = kConvergenceProbe, PartCache* parts = nullptr);

// `options` at the count convergedSamples chooses (referenceMaxSamples is
// the cap), and that count and its change in perAxis and change: what a
// figure renders its reference or exact statistics with and prints beside them.
// `parts`, where the study keeps one: the tables and pyramids each probe
// render needs are built once for the study (PartCache), not per render.
FilterOptions atConvergedSamples(const GraphPattern& graph, const FilterOptions& options, const Camera& camera,
                                 double tolerance, int& perAxis, double& change, PartCache* parts = nullptr);

// A figure's reference tolerance: InputError naming referenceTolerance
// outside (0, 0.1].
void validateReferenceTolerance(double tolerance);

}  // namespace stochtex
