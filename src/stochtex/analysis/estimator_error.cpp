#include "stochtex/analysis/estimator_error.h"

#include <array>
#include <cmath>
#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/filter/pyramid.h"

namespace stochtex {

void validateEstimatorErrorOptions(const EstimatorErrorOptions& options, int exampleSize) {
    if (options.count < 1 || options.count > 1000000)
        throw InputError::parameter("count", "must be in [1, 1e6], got " + std::to_string(options.count));
    if (options.footprints.empty()) throw InputError::parameter("footprints", "must list at least one size");
    for (int s : options.footprints)
        if (s < 1 || s > 4 * exampleSize)
            throw InputError::parameter("footprints", "must be in [1, " + std::to_string(4 * exampleSize) +
                                                          "] texels, got " + std::to_string(s));
}

std::vector<EstimatorError> measureEstimatorErrors(const TiledField& field, const EstimatorErrorOptions& options,
                                                   const std::function<void(int)>& progress) {
    if (field.channelCount() != 2)
        throw std::invalid_argument("measureEstimatorErrors: needs a field of 2 channels, got " +
                                    std::to_string(field.channelCount()));
    const int w = field.exampleSize();
    if (!isPowerOfTwo(w)) throw InputError("estimator errors: examples must be power-of-two sized");
    validateEstimatorErrorOptions(options, w);
    const FootprintEstimator estimator(field, false);
    // Global statistics: the top pyramid level is the whole example.
    std::array<double, 2> globalMean{}, globalSigma{};
    {
        const auto top = estimator.texel(0.0, 0.0, estimator.maxLod(), VarianceEstimator::Paper);
        for (size_t a = 0; a < 2; ++a) {
            globalMean[a] = top.mean[a];
            globalSigma[a] = std::sqrt(std::max(0.0f, top.var[a]));
        }
    }
    // Every estimator of kVarianceEstimatorNames, then "global".
    std::vector<std::string> names;
    for (const auto& [name, mode] : kVarianceEstimatorNames) names.push_back(name);
    names.push_back("global");
    const size_t estimators = names.size();
    std::vector<EstimatorError> rows;
    int sizeIndex = 0;
    for (int s : options.footprints) {
        // Per footprint and estimator: |Δμ|, |Δμ|/μ, |Δσ|, |Δσ|/σ summed over
        // the two components, plus the references.
        struct Sample {
            std::vector<std::array<double, 4>> e;  // per estimator
            double mu = 0, sigma = 0;
        };
        std::vector<Sample> samples(static_cast<size_t>(options.count));
        const double side = double(s) / w;
        const Jacobian j{side, 0.0, 0.0, side};
        parallelRows(options.count, [&](int k0, int k1) {
            for (int k = k0; k < k1; ++k) {
                const UInt3 h = pcg3d({uint32_t(k), uint32_t(s), options.seed});
                // Centres anywhere over 64 periods: every tile arrangement.
                const double u = 64.0 * unitFloat(h.x), v = 64.0 * unitFloat(h.y);
                const FootprintStats exact = bruteForceStats(field, u, v, j, options.maxSamplesPerAxis);
                const Footprint f = makeFootprint(u, v, j, w, estimator.maxLod(), 1);
                std::vector<FootprintStats> estimates;
                for (const auto& [name, mode] : kVarianceEstimatorNames)
                    estimates.push_back(estimator.estimate(f, mode));
                Sample& out = samples[size_t(k)];
                out = Sample{std::vector<std::array<double, 4>>(estimators), 0, 0};
                const double refMu[2] = {exact.mean[0], exact.mean[1]};
                const double refSigma[2] = {exact.sigmaX(), exact.sigmaY()};
                for (int a = 0; a < 2; ++a) {
                    std::vector<double> estMu, estSigma;
                    for (const FootprintStats& e : estimates) {
                        estMu.push_back(e.mean[size_t(a)]);
                        estSigma.push_back(a == 0 ? e.sigmaX() : e.sigmaY());
                    }
                    estMu.push_back(globalMean[size_t(a)]);
                    estSigma.push_back(globalSigma[size_t(a)]);
                    for (size_t e = 0; e < estimators; ++e) {
                        const double dm = std::abs(estMu[e] - refMu[a]), ds = std::abs(estSigma[e] - refSigma[a]);
                        out.e[e][0] += dm;
                        out.e[e][1] += refMu[a] != 0 ? dm / std::abs(refMu[a]) : 0.0;
                        out.e[e][2] += ds;
                        out.e[e][3] += refSigma[a] > 0 ? ds / refSigma[a] : 0.0;
                    }
                    out.mu += refMu[a];
                    out.sigma += refSigma[a];
                }
            }
        });
        const double n = 2.0 * options.count;
        for (size_t e = 0; e < estimators; ++e) {
            EstimatorError r;
            r.footprint = s;
            r.estimator = names[e];
            r.values = 2 * options.count;
            for (const Sample& smp : samples) {  // in index order: deterministic sums
                r.muAbs += smp.e[e][0];
                r.muRel += smp.e[e][1];
                r.sigmaAbs += smp.e[e][2];
                r.sigmaRel += smp.e[e][3];
                r.meanMu += smp.mu;
                r.meanSigma += smp.sigma;
            }
            r.muAbs /= n;
            r.muRel /= n;
            r.sigmaAbs /= n;
            r.sigmaRel /= n;
            r.meanMu /= n;
            r.meanSigma /= n;
            rows.push_back(r);
        }
        if (progress) progress(++sizeIndex);
    }
    return rows;
}

}  // namespace stochtex
