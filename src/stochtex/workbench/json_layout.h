#pragma once
// Writing an edited JSON document the way its file was written, so that a
// one-number edit in the workbench is a one-line diff: nlohmann::json keeps
// an object's keys sorted and dump() lays everything out its own way.
//
// layoutLike(value, original) writes `value` taking from `original` (the
// file's text, which parses as JSON) everything that still applies: a part
// of the value equal to the original's at the same place is copied as its
// text (spacing, line breaks, key order, number spelling); an object or
// array that changed keeps its original key order (new keys after, in
// sorted order) and its layout (on one line if it was, else one member a
// line at the original's indentation); what is new is written on one line,
// with ", " and ": " as separators.
#include <string>

#include <nlohmann/json.hpp>

namespace stochtex {

// `original` must parse (std::invalid_argument otherwise); "" writes `value`
// as dump(2) does. The result always parses back to `value`.
std::string layoutLike(const nlohmann::json& value, const std::string& original);

}  // namespace stochtex
