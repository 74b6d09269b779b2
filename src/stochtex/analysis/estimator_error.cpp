#include "stochtex/analysis/estimator_error.h"

#include <algorithm>
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

struct EstimatorErrorSampler::State {
    TiledField field;
    EstimatorErrorOptions options;
    FootprintEstimator estimator;
    std::array<double, 2> globalMean{}, globalSigma{};
};

EstimatorErrorSampler::EstimatorErrorSampler(const TiledField& field, const EstimatorErrorOptions& options) {
    if (field.channelCount() != 2)
        throw std::invalid_argument("estimator errors: need a field of 2 channels, got " +
                                    std::to_string(field.channelCount()));
    const int w = field.exampleSize();
    if (!isPowerOfTwo(w)) throw InputError("estimator errors: examples must be power-of-two sized");
    validateEstimatorErrorOptions(options, w);
    auto state = std::make_unique<State>(State{field, options, FootprintEstimator(field, false), {}, {}});
    // Global statistics: the top pyramid level is the whole example.
    const auto top = state->estimator.texel(0.0, 0.0, state->estimator.maxLod(), VarianceEstimator::Paper);
    for (size_t a = 0; a < 2; ++a) {
        state->globalMean[a] = top.mean[a];
        state->globalSigma[a] = std::sqrt(std::max(0.0f, top.var[a]));
    }
    state_ = std::move(state);
}

EstimatorErrorSampler::~EstimatorErrorSampler() = default;

const std::vector<std::string>& EstimatorErrorSampler::estimators() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& [name, mode] : kVarianceEstimatorNames) n.push_back(name);
        n.push_back("global");
        return n;
    }();
    return names;
}

size_t EstimatorErrorSampler::termsPerFootprint() { return estimators().size() * 4 + 2; }

std::vector<double> EstimatorErrorSampler::terms(int s, int first, int count) const {
    const EstimatorErrorOptions& o = state_->options;
    const int w = state_->field.exampleSize();
    if (s < 1 || s > 4 * w)
        throw InputError::parameter("footprint",
                                    "must be in [1, " + std::to_string(4 * w) + "] texels, got " + std::to_string(s));
    if (first < 0 || first > o.count)
        throw InputError::parameter("first", "must be in [0, " + std::to_string(o.count) +
                                                 "] (the options' count), got " + std::to_string(first));
    if (count < 0 || count > o.count - first)
        throw InputError::parameter("count", "must be in [0, " + std::to_string(o.count - first) +
                                                 "] (the footprints from first on), got " + std::to_string(count));
    const size_t estimators = EstimatorErrorSampler::estimators().size(), width = termsPerFootprint();
    std::vector<double> out(size_t(count) * width, 0.0);
    const double side = double(s) / w;
    const Jacobian j{side, 0.0, 0.0, side};
    parallelRows(count, [&](int i0, int i1) {
        for (int i = i0; i < i1; ++i) {
            const int k = first + i;
            const UInt3 h = pcg3d({uint32_t(k), uint32_t(s), o.seed});
            // Centres anywhere over 64 periods: every tile arrangement.
            const double u = 64.0 * unitFloat(h.x), v = 64.0 * unitFloat(h.y);
            const FootprintStats exact = bruteForceStats(state_->field, u, v, j, o.maxSamplesPerAxis);
            const Footprint f = makeFootprint(u, v, j, w, state_->estimator.maxLod(), 1);
            std::vector<FootprintStats> estimates;
            for (const auto& [name, mode] : kVarianceEstimatorNames)
                estimates.push_back(state_->estimator.estimate(f, mode));
            double* t = out.data() + size_t(i) * width;
            const double refMu[2] = {exact.mean[0], exact.mean[1]};
            const double refSigma[2] = {exact.sigmaX(), exact.sigmaY()};
            for (int a = 0; a < 2; ++a) {
                std::vector<double> estMu, estSigma;
                for (const FootprintStats& e : estimates) {
                    estMu.push_back(e.mean[size_t(a)]);
                    estSigma.push_back(a == 0 ? e.sigmaX() : e.sigmaY());
                }
                estMu.push_back(state_->globalMean[size_t(a)]);
                estSigma.push_back(state_->globalSigma[size_t(a)]);
                for (size_t e = 0; e < estimators; ++e) {
                    const double dm = std::abs(estMu[e] - refMu[a]), ds = std::abs(estSigma[e] - refSigma[a]);
                    t[4 * e] += dm;
                    t[4 * e + 1] += refMu[a] != 0 ? dm / std::abs(refMu[a]) : 0.0;
                    t[4 * e + 2] += ds;
                    t[4 * e + 3] += refSigma[a] > 0 ? ds / refSigma[a] : 0.0;
                }
                t[4 * estimators] += refMu[a];
                t[4 * estimators + 1] += refSigma[a];
            }
        }
    });
    return out;
}

std::vector<EstimatorError> summarizeEstimatorErrors(int footprint, const std::vector<double>& terms) {
    const std::vector<std::string>& names = EstimatorErrorSampler::estimators();
    const size_t estimators = names.size(), width = EstimatorErrorSampler::termsPerFootprint();
    if (terms.empty() || terms.size() % width != 0)
        throw InputError::parameter("terms", "must hold whole footprints of " + std::to_string(width) + " terms, got " +
                                                 std::to_string(terms.size()));
    const size_t count = terms.size() / width;
    const double n = 2.0 * double(count);
    std::vector<EstimatorError> rows;
    for (size_t e = 0; e < estimators; ++e) {
        EstimatorError r;
        r.footprint = footprint;
        r.estimator = names[e];
        r.values = int(2 * count);
        for (size_t k = 0; k < count; ++k) {  // in index order: deterministic sums
            const double* t = terms.data() + k * width;
            r.muAbs += t[4 * e];
            r.muRel += t[4 * e + 1];
            r.sigmaAbs += t[4 * e + 2];
            r.sigmaRel += t[4 * e + 3];
            r.meanMu += t[4 * estimators];
            r.meanSigma += t[4 * estimators + 1];
        }
        r.muAbs /= n;
        r.muRel /= n;
        r.sigmaAbs /= n;
        r.sigmaRel /= n;
        r.meanMu /= n;
        r.meanSigma /= n;
        rows.push_back(r);
    }
    return rows;
}

std::vector<EstimatorError> measureEstimatorErrors(const TiledField& field, const EstimatorErrorOptions& options,
                                                   const std::function<void(int)>& progress) {
    const EstimatorErrorSampler sampler(field, options);
    std::vector<EstimatorError> rows;
    int sizeIndex = 0;
    for (int s : options.footprints) {
        const std::vector<EstimatorError> size = summarizeEstimatorErrors(s, sampler.terms(s, 0, options.count));
        rows.insert(rows.end(), size.begin(), size.end());
        if (progress) progress(++sizeIndex);
    }
    return rows;
}

}  // namespace stochtex
