#include "stochtex/pattern/filter_options.h"

#include "stochtex/core/error.h"

namespace stochtex {

void validateFilterOptions(const FilterOptions& options) {
    if (options.aniso < 1 || options.aniso > kMaxAnisotropy)
        throw InputError::parameter("aniso", "must be in [1, " + std::to_string(kMaxAnisotropy) + "], got " +
                                                 std::to_string(options.aniso));
    if (options.referenceMaxSamples < 1 || options.referenceMaxSamples > 4096)
        throw InputError::parameter("referenceMaxSamples",
                                    "must be in [1, 4096], got " + std::to_string(options.referenceMaxSamples));
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

}  // namespace stochtex
