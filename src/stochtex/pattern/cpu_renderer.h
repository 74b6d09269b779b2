#pragma once
// The CPU evaluator of a pattern file as a ViewRenderer that owns what it
// reads: the file's program (GraphPattern: a graph's, or a plain pattern's
// "two leaves → colormap") filtered by FilteredGraph; the lean response of a
// plain pattern's normal map, which its program does not carry yet, by
// FilteredPattern.
#include <memory>

#include "stochtex/pattern/filtered_pattern.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

std::unique_ptr<ViewRenderer> makeCpuRenderer(const PatternSpec& spec, const FilterOptions& options);

}  // namespace stochtex
