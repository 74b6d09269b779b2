#pragma once
// Which footprint estimator a filter reads its statistics with: a parameter
// of the filter options, the CLI, pattern files ("estimator") and the
// exports, apart from the estimator itself (filter/footprint_stats.h) so
// that what only names one need not include the pyramids.
#include "stochtex/core/enum_names.h"

namespace stochtex {

enum class VarianceEstimator {
    Paper,         // eq. 12/14/15: per-texel variances from the V_l pyramid
    DeliotHeitz,   // one constant within-texel variance per LOD [DH19]
    SubProbes,     // the paper's, each probe as 2×2 probes one level finer (kernel/estimate.glsl; 4× the fetches)
    SubProbes4x4,  // the same as 4×4 probes two levels finer (16× the fetches)
    SubProbes8x8FineMeans,  // 8×8 sub-probes three levels finer, each one's mean from 2×2 reads one level
                            // finer still (320× the fetches; 64× where a sub-probe is at level 0)
};
// The paper's first: the studies' main columns are the default estimator's
// (FilterOptions::estimator), then a column per name after it.
inline const EnumNames<VarianceEstimator> kVarianceEstimatorNames{
    {"paper", VarianceEstimator::Paper},
    {"deliot-heitz", VarianceEstimator::DeliotHeitz},
    {"sub-probes", VarianceEstimator::SubProbes},
    {"sub-probes-4x4", VarianceEstimator::SubProbes4x4},
    {"sub-probes-8x8-fine-means", VarianceEstimator::SubProbes8x8FineMeans}};
// The sub-probes per side of a probe that an estimator reads (the kernel's
// subProbes: 2 for SubProbes, 4 and 8 for the 4×4 and 8×8 ones, else 1).
inline int subProbesOf(VarianceEstimator e) {
    if (e == VarianceEstimator::SubProbes) return 2;
    if (e == VarianceEstimator::SubProbes4x4) return 4;
    return e == VarianceEstimator::SubProbes8x8FineMeans ? 8 : 1;
}
// Whether its sub-probes read their means from a 2×2 grid one level finer
// (the kernel's fineMeans, kernel/estimate.glsl).
inline bool fineMeansOf(VarianceEstimator e) { return e == VarianceEstimator::SubProbes8x8FineMeans; }

}  // namespace stochtex
