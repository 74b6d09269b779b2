#pragma once
// One name table per enum, declared next to the enum and used by every
// reader of names: the parsers here, the CLI's transformers (CLI11 takes the
// same vector of pairs), the JSON reader and the bake manifest. The first
// name of a value is its canonical name; later ones are aliases.
#include <string>
#include <utility>
#include <vector>

#include "stochtex/core/error.h"

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

// InputError "what: unknown "s" (expected a, b or c)" for a name not in the table.
template <class E>
E parseEnum(const EnumNames<E>& names, const std::string& s, const std::string& what) {
    std::string expected;
    for (size_t i = 0; i < names.size(); ++i) {
        if (names[i].first == s) return names[i].second;
        expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i].first;
    }
    throw InputError(what + ": unknown \"" + s + "\" (expected " + expected + ")");
}

}  // namespace stochtex
