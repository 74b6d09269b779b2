#pragma once
// The pattern file format (JSON) and its validation. A pattern is
//   { "name", "seed", "size", "scale", "offsets", "grid_density",
//     "noise_x": NOISE, "noise_y": NOISE | "quadrature", "colormap": COLORMAP,
//     "normal_map": NORMAL_MAP (optional) }
// or the same header with "nodes" and "output": a texture graph
// (texture_graph.h),
// documented in full in docs/PATTERNS.md. Every error names the source and
// the JSON pointer of the value at fault.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_file.h"
#include "stochtex/pattern/pattern_parts.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

PatternSpec parsePatternSpec(const JsonReader& r, const std::filesystem::path& baseDir);
// Reads a pattern or graph file (InputError naming it if missing or wrong).
PatternSpec loadPatternFile(const std::string& path);

// Gives noise without an explicit seed a seed derived from the pattern seed
// (axis 0 or 1), so one pattern seed controls everything.
uint32_t noiseSeed(const PatternSpec& spec, int axis);

// The pattern's view (its size and scale, offset 0) with what is given
// instead: size {N} or {W, H}, a scale, offset {u, v} in texels (the CLI's
// --size/--scale/--offset, Python's keywords). InputError naming size or
// offset for a wrong count, then validateView for `use`.
View patternView(const PatternSpec& spec, std::span<const int> size, std::optional<double> scale,
                 std::span<const double> offset, ViewUse use = ViewUse::Render);

}  // namespace stochtex
