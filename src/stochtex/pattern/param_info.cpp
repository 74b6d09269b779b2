#include "stochtex/pattern/param_info.h"

#include <cmath>

#include "stochtex/core/error.h"

namespace stochtex {

const char* paramTypeName(ParamType t) {
    switch (t) {
        case ParamType::Number: return "number";
        case ParamType::Integer: return "integer";
        case ParamType::Boolean: return "boolean";
        case ParamType::Seed: return "seed";
        case ParamType::Path: return "path";
        case ParamType::Components: return "components";
        case ParamType::Colormap: return "colormap";
        case ParamType::Curve: return "curve";
        case ParamType::Colour: return "colour";
        case ParamType::Choice: break;
    }
    return "choice";
}

double ParamInfo::typical() const {
    if (fallback.is_number()) return fallback.get<double>();
    if (sample.is_number()) return sample.get<double>();
    return min;
}

double readNumber(const JsonReader& object, const ParamInfo& p) {
    if (p.required()) return object.at(p.name).number(p.min, p.max);
    return object.number(p.name, p.fallback.get<double>(), p.min, p.max);
}

ParamInfo optionParam(std::string name, ParamType type, std::string description, double fallback, double min,
                      double max, std::string flag) {
    // An integer's default as a JSON integer, as a file would give it.
    const nlohmann::json value =
        type == ParamType::Integer ? nlohmann::json((long long)fallback) : nlohmann::json(fallback);
    ParamInfo p{std::move(name), type, std::move(description), value, min, max};
    p.flag = std::move(flag);
    return p;
}

double checkNumber(const ParamInfo& p, double value, const std::string& unit) {
    if (!(std::isfinite(value) && value >= p.min && value <= p.max))
        throw InputError::parameter(p.name, "must be in [" + formatValue(p.min) + ", " + formatValue(p.max) + "]" +
                                                unit + ", got " + formatValue(value));
    return value;
}

int checkInteger(const ParamInfo& p, long long value) {
    if (value < (long long)p.min || value > (long long)p.max)
        throw InputError::parameter(p.name, "must be in [" + std::to_string((long long)p.min) + ", " +
                                                std::to_string((long long)p.max) + "], got " + std::to_string(value));
    return int(value);
}

std::string kebabCase(std::string_view name) {
    std::string flag;
    for (const char c : name) {
        if (c >= 'A' && c <= 'Z') {
            flag += '-';
            flag += char(c - 'A' + 'a');
        } else {
            flag += c;
        }
    }
    return flag;
}

int readInteger(const JsonReader& object, const ParamInfo& p) {
    if (p.required()) return object.at(p.name).integer(int(p.min), int(p.max));
    return object.integer(p.name, p.fallback.get<int>(), int(p.min), int(p.max));
}

}  // namespace stochtex
