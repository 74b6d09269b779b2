#pragma once
// A parameter described once — its JSON name, type, meaning, default and
// range — so that one entry drives the parsing and validation of a file,
// the listing of `stochtex nodes`, the workbench's widgets and the
// per-node benchmarks. Graph nodes (graph_nodes.h) and the members of a
// pattern file (pattern_members.h) are tables of these.
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/pattern/json_reader.h"

namespace stochtex {

enum class ParamType {
    Number,   // a finite number in [min, max]
    Integer,  // an integer in [min, max]
    Boolean,
    Seed,        // an integer in [0, 2³² − 1]; unset: derived from the graph's seed and the node's id
    Path,        // an image file, relative to the graph file's folder
    Components,  // spectrum components, as a pattern file's noise (docs/PATTERNS.md)
    Colormap,    // a COLORMAP object, as a pattern file's (docs/PATTERNS.md)
    Curve,       // [[x, y], ...]: at least 2 points, x strictly increasing in [0, 1]
    Colour,      // "#rrggbb" or [r, g, b] in [0, 1], sRGB components (decoded to linear light)
    Choice,      // one of ParamInfo::choices (a string)
};
const char* paramTypeName(ParamType t);

struct ParamInfo {
    std::string name;
    ParamType type;
    std::string description;
    nlohmann::json fallback;  // the default; null: required (or, for a seed, derived)
    double min = 0, max = 0;  // Number and Integer
    // For a required parameter: a typical value, used where a graph is built
    // from the table alone (sampleNodeGraph). Null for paths (the caller's).
    nlohmann::json sample = nullptr;
    std::vector<std::string> choices = {};  // Choice
    // Where a widget's drag ends when max is far beyond the useful values
    // (frequencies go to 10⁴ cycles, a few hundred are typical); NaN: max.
    // A typed value may still go up to max.
    double dragMax = std::nan("");
    // The CLI's flag for it, without the dashes ("tilt" for --tilt), where a
    // command sets it from one (apps/stochtex: addParameterOption); empty
    // for a parameter only files set.
    std::string flag = {};

    bool required() const { return fallback.is_null(); }
    // The default, or for a required parameter its sample (a number: min).
    double typical() const;
    // The top of a widget's drag range: dragMax, or max.
    double dragTop() const { return std::isnan(dragMax) ? max : dragMax; }
};

// A Number or Integer parameter of `object`: its member `p.name` within
// [p.min, p.max], or p's default when absent (InputError at the member when
// it is out of range, or absent and required).
double readNumber(const JsonReader& object, const ParamInfo& p);
int readInteger(const JsonReader& object, const ParamInfo& p);

// The entry of a number an option struct holds and a CLI flag sets
// (`flag` without its dashes): no sample, choices or drag range.
ParamInfo optionParam(std::string name, ParamType type, std::string description, double fallback, double min,
                      double max, std::string flag);

// A value set other than from a file (an option struct's member), checked
// against its entry: InputError::parameter(p.name, "must be in [min, max]
// UNIT, got VALUE") when it is outside or not finite; `unit` (" degrees")
// follows the range.
double checkNumber(const ParamInfo& p, double value, const std::string& unit = "");
int checkInteger(const ParamInfo& p, long long value);

// A camelCase parameter name as a flag: "truthSamples" → "truth-samples".
std::string kebabCase(std::string_view name);

// A number member of an option struct described by its entry. One table of
// these per struct, beside the study or tool that reads it, states each
// number once — name, meaning, range, flag — for the library's check
// (checkMembers) and the CLI's options (apps/stochtex:
// addParameterOptions). The default is the struct's own initialiser, so
// it is not written twice; the flag is the name in kebab case unless given.
template <class Options>
struct OptionMember {
    ParamInfo info;
    std::variant<int Options::*, double Options::*> member;

    template <class T>
    requires std::is_same_v<T, int> || std::is_same_v<T, double> OptionMember(std::string name, std::string description,
                                                                              double min, double max, T Options::*m,
                                                                              std::string flag = {})
        : info(optionParam(name, std::is_same_v<T, int> ? ParamType::Integer : ParamType::Number,
                           std::move(description), double(defaults().*m), min, max,
                           flag.empty() ? kebabCase(name) : std::move(flag))),
          member(m) {}

private:
    // One default-constructed struct for every entry of the table.
    static const Options& defaults() {
        static const Options d{};
        return d;
    }
};

// Each member of `o` that `members` describes within its entry's range
// (InputError at the first that is not: checkNumber, checkInteger).
template <class Options>
void checkMembers(const Options& o, std::span<const OptionMember<Options>> members) {
    for (const OptionMember<Options>& m : members)
        std::visit(
            [&](auto p) {
                if constexpr (std::is_same_v<decltype(p), int Options::*>)
                    checkInteger(m.info, o.*p);
                else
                    checkNumber(m.info, o.*p);
            },
            m.member);
}

// The entry of the member called `name` (logic_error when there is none: a
// caller's typo, not the user's).
template <class Options>
const OptionMember<Options>& optionMember(std::span<const OptionMember<Options>> members, std::string_view name) {
    for (const OptionMember<Options>& m : members)
        if (m.info.name == name) return m;
    throw std::logic_error("no option member " + std::string(name));
}

}  // namespace stochtex
