#pragma once
// The CPU evaluator of a pattern file as a ViewRenderer that owns what it
// reads: a plain pattern's FilteredPattern, or a texture graph's
// FilteredGraph where the file is not a pattern H∘N.
#include <memory>

#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

std::unique_ptr<ViewRenderer> makeCpuRenderer(const PatternSpec& spec, const FilterOptions& options);

}  // namespace stochtex
