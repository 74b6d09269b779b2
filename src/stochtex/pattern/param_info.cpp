#include "stochtex/pattern/param_info.h"

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

int readInteger(const JsonReader& object, const ParamInfo& p) {
    if (p.required()) return object.at(p.name).integer(int(p.min), int(p.max));
    return object.integer(p.name, p.fallback.get<int>(), int(p.min), int(p.max));
}

}  // namespace stochtex
