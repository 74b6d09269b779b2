#pragma once
// Suggestions for a mistyped name (a command, an option, a preset, a JSON
// choice): "did you mean X?" wherever a name is refused.
#include <string>
#include <vector>

namespace stochtex {

// Optimal string alignment distance: Levenshtein plus swapped neighbours ("rednre").
size_t editDistance(const std::string& a, const std::string& b);

// The candidates `given` is probably a mistyping of: the nearest by edit
// distance when at most a third of the name is wrong (at least 1, at most 3
// edits); else those it abbreviates (same first letter, its letters in
// order: "fig11" → "figure11"), when at most three do. Empty when none.
std::vector<std::string> closestNames(const std::string& given, const std::vector<std::string>& candidates);

// " (did you mean X?)", " (did you mean X or Y?)", or "" (closestNames).
std::string didYouMean(const std::string& given, const std::vector<std::string>& candidates);

}  // namespace stochtex
