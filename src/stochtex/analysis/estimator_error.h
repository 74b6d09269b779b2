#pragma once
// Accuracy of the footprint estimators (paper §6.1, Table 1): over random
// square footprints of s×s texels, the mean absolute and mean relative error
// of μ̂ and σ̂ against the exact footprint statistics of the tiled-and-blended
// noise (bruteForceStats: 2 samples per texel and axis).
//
// Estimators compared:
//   paper        — eq. 8 and eq. 12 on the E_l / V_l pyramids;
//   deliot-heitz — the same mean, one constant variance per level [DH19];
//   sub-probes   — the paper's, each probe as 2×2 probes one level finer;
//   sub-probes-4x4 — the same as 4×4 probes two levels finer;
//   sub-probes-8x8-fine-means — the same, each sub-probe's mean from 2×2
//                  reads one level finer (kernel/estimate.glsl);
//   global       — no footprint information: μ_E and σ_E of the whole
//                  example (what a pixel falls back to without filtering
//                  data; every estimator should beat it).
// Both components of N are measured and pooled (2 values per footprint).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stochtex/noise/tiled_field.h"

namespace stochtex {

struct EstimatorErrorOptions {
    std::vector<int> footprints{2, 4, 8, 16, 32, 64, 128};  // s, texels per side
    int count = 1000;                                       // footprints per size
    uint32_t seed = 1;                                      // footprint centres
    int maxSamplesPerAxis = 512;                            // exact statistics
};

struct EstimatorError {
    int footprint = 0;
    std::string estimator;
    double muAbs = 0, muRel = 0;        // mean |μ̂ − μ|, mean |μ̂ − μ|/|μ|
    double sigmaAbs = 0, sigmaRel = 0;  // mean |σ̂ − σ|, mean |σ̂ − σ|/σ
    double meanMu = 0, meanSigma = 0;   // mean reference μ and σ
    int values = 0;                     // footprints × 2 components
};

// InputError for a count outside [1, 1e6] or footprints outside
// [1, 4·exampleSize].
void validateEstimatorErrorOptions(const EstimatorErrorOptions& options, int exampleSize);

// The per-footprint terms of those errors, for footprints split across
// processes (a Dask cluster, stochtex/dask.py): footprint k of size s depends
// only on (k, s, options.seed), so the terms of footprints [first, first +
// count) can be measured anywhere, and summarizeEstimatorErrors over all of
// them in index order gives exactly measureEstimatorErrors' rows.
class EstimatorErrorSampler {
public:
    // InputError for unusable options (validateEstimatorErrorOptions) or
    // examples that are not power-of-two sized; std::invalid_argument for a
    // field without two channels.
    EstimatorErrorSampler(const TiledField& field, const EstimatorErrorOptions& options);
    ~EstimatorErrorSampler();
    // The estimators measured, in row order: kVarianceEstimatorNames', then "global".
    static const std::vector<std::string>& estimators();
    // Terms per footprint: per estimator |Δμ|, |Δμ|/|μ|, |Δσ|, |Δσ|/σ (each
    // summed over the two components), then μ and σ summed over them.
    static size_t termsPerFootprint();
    // count × termsPerFootprint() terms, footprint-major; multi-threaded,
    // the result does not depend on threads. InputError for a size outside
    // the options' range, first outside [0, options.count] or count beyond it.
    std::vector<double> terms(int footprint, int first, int count) const;

private:
    struct State;
    std::unique_ptr<const State> state_;
};

// Rows of one footprint size (EstimatorError, in estimators() order) from
// the terms of all its footprints in index order.
std::vector<EstimatorError> summarizeEstimatorErrors(int footprint, const std::vector<double>& terms);

// The errors of a two-channel field's estimators (its grid density and
// tile offsets; covariances are not measured, so its sharing does not
// matter). Rows ordered by footprint, then estimator (kVarianceEstimatorNames'
// order: paper, deliot-heitz, sub-probes, sub-probes-4x4,
// sub-probes-8x8-fine-means; then global). Multi-threaded over footprints; the
// result does not depend on threads. std::invalid_argument for a field
// without two channels.
std::vector<EstimatorError> measureEstimatorErrors(const TiledField& field, const EstimatorErrorOptions& options,
                                                   const std::function<void(int)>& progress = {});

}  // namespace stochtex
