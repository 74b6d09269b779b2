#include "stochtex/pattern/filter_options.h"

#include "stochtex/core/error.h"

namespace stochtex {

FootprintStats fieldStatistics(const TiledField& f) {
    double mean[2] = {0, 0}, m2[3] = {0, 0, 0};
    const auto& x = f.channel(0).example().values().data();
    const auto& y = f.channel(1).example().values().data();
    for (size_t i = 0; i < x.size(); ++i) {
        mean[0] += x[i];
        mean[1] += y[i];
    }
    mean[0] /= double(x.size());
    mean[1] /= double(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
        const double dx = x[i] - mean[0], dy = y[i] - mean[1];
        m2[0] += dx * dx;
        m2[1] += dy * dy;
        m2[2] += dx * dy;
    }
    FootprintStats s;
    s.mean = {float(mean[0]), float(mean[1])};
    s.varX = float(m2[0] / double(x.size()));
    s.varY = float(m2[1] / double(x.size()));
    s.cov = float(m2[2] / double(x.size()));
    return s;
}

std::array<double, 2> exampleMoments(const NoiseExample& example) {
    const auto& v = example.values().data();
    double sum = 0, sum2 = 0;
    for (const float x : v) sum += x;
    const double mean = sum / double(v.size());
    for (const float x : v) sum2 += (x - mean) * (x - mean);
    return {mean, sum2 / double(v.size())};
}

void validateFilterOptions(const FilterOptions& options) {
    if (options.aniso < 1 || options.aniso > kMaxAnisotropy)
        throw InputError::parameter("aniso", "must be in [1, " + std::to_string(kMaxAnisotropy) + "], got " +
                                                 std::to_string(options.aniso));
    if (options.referenceMaxSamples < 1 || options.referenceMaxSamples > 4096)
        throw InputError::parameter("referenceMaxSamples",
                                    "must be in [1, 4096], got " + std::to_string(options.referenceMaxSamples));
}

NamedFilter parseFilter(const std::string& name) { return parseEnum(kFilterNames, name, "filter"); }

std::string filterName(const FilterOptions& options) {
    for (const auto& [name, filter] : kFilterNames)
        if (filter == options.filter()) return name;
    // Another response over a named filter's statistics: "smooth/lean".
    if (options.response.kind != ResponseKind::PrefilteredColormap) {
        const NamedFilter colours{options.source, {ResponseKind::PrefilteredColormap, options.response.prefilter}};
        for (const auto& [name, filter] : kFilterNames)
            if (filter == colours)
                return name + "/" + enumName(kResponseKindNames, options.response.kind) +
                       (options.response.covariance ? "" : " without covariance");
    }
    return enumName(kStatisticsSourceNames, options.source) + "/" + enumName(kResponseKindNames, options.response.kind);
}

}  // namespace stochtex
