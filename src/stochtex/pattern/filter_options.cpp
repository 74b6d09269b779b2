#include "stochtex/pattern/filter_options.h"

#include "stochtex/core/error.h"
#include "stochtex/pattern/param_info.h"

namespace stochtex {

const ParamInfo& anisoParam() {
    static const ParamInfo p =
        optionParam("aniso", ParamType::Integer, "Anisotropic probes K (1 = isotropic trilinear)", kDefaultAniso, 1,
                    kMaxAnisotropy, "aniso");
    return p;
}

const ParamInfo& referenceMaxSamplesParam() {
    static const ParamInfo p =
        optionParam("referenceMaxSamples", ParamType::Integer,
                    "Max samples per axis and pixel of the exact and reference filters (n = clamp(2·extent, 8, this))",
                    FilterOptions{}.referenceMaxSamples, 1, 4096, "reference-samples");
    return p;
}

void validateFilterOptions(const FilterOptions& options) {
    checkInteger(anisoParam(), options.aniso);
    checkInteger(referenceMaxSamplesParam(), options.referenceMaxSamples);
    if (options.referenceMinSamples < 1 || options.referenceMinSamples > 4096)
        throw InputError::parameter("referenceMinSamples",
                                    "must be in [1, 4096], got " + std::to_string(options.referenceMinSamples));
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

std::string filterLabel(const FilterOptions& options) {
    const bool otherEstimator =
        options.source == StatisticsSource::Estimators && options.estimator != FilterOptions{}.estimator;
    return filterName(options) + (otherEstimator ? "/" + enumName(kVarianceEstimatorNames, options.estimator) : "");
}

}  // namespace stochtex
