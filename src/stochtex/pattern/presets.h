#pragma once
// Pattern presets: the JSON files of data/presets, embedded at build time so
// the binary works without the source tree.
#include <string>
#include <vector>

#include "stochtex/pattern/pattern_spec.h"

namespace stochtex {

std::vector<std::string> presetNames();  // sorted
// The preset's JSON text; InputError listing the known names if unknown.
const char* presetText(const std::string& name);
PatternSpec loadPreset(const std::string& name);

}  // namespace stochtex
