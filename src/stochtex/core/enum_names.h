#pragma once
// One name table per enum, declared next to the enum and used by every
// reader of names: the parsers here, the CLI's transformers (CLI11 takes the
// same vector of pairs), the JSON reader and the bake manifest. The first
// name of a value is its canonical name; later ones are aliases.
#include <string>
#include <utility>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/names.h"

namespace stochtex {

template <class E>
using EnumNames = std::vector<std::pair<std::string, E>>;

// The canonical name of v ("?" if the table lacks it: a bug).
template <class E>
const std::string& enumName(const EnumNames<E>& names, E v) {
    static const std::string unknown = "?";
    for (const auto& [name, value] : names)
        if (value == v) return name;
    return unknown;
}

// The canonical names in table order, joined as "a, b or c" (lastSeparator
// " or ") or "a, b, c" (lastSeparator ", ").
template <class E>
std::string canonicalNames(const EnumNames<E>& names, const std::string& lastSeparator = " or ") {
    std::vector<std::string> canonical;
    for (const auto& [name, value] : names)
        if (enumName(names, value) == name) canonical.push_back(name);
    std::string joined;
    for (size_t i = 0; i < canonical.size(); ++i)
        joined += (i == 0 ? "" : i + 1 == canonical.size() ? lastSeparator : ", ") + canonical[i];
    return joined;
}

// The value named s, or nullptr.
template <class E>
const E* findEnum(const EnumNames<E>& names, const std::string& s) {
    for (const auto& [name, value] : names)
        if (name == s) return &value;
    return nullptr;
}

// The value named s; for a name not in the table, InputError naming the
// parameter: "what must be a, b or c, got "s"" (canonical names only),
// with " (did you mean b?)" for a likely typo.
template <class E>
E parseEnum(const EnumNames<E>& names, const std::string& s, const std::string& what) {
    if (const E* v = findEnum(names, s)) return *v;
    std::vector<std::string> all;
    for (const auto& [name, value] : names) all.push_back(name);
    throw InputError::parameter(what, "must be " + canonicalNames(names) + ", got \"" + s + "\"" + didYouMean(s, all));
}

}  // namespace stochtex
