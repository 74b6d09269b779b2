#pragma once
// The CPU evaluator of a pattern file as a ViewRenderer that owns what it
// reads: the file's program under the options' response (GraphPattern::build:
// a graph's, a plain pattern's "two leaves → colormap", or its normal map's
// lean) filtered by FilteredGraph.
#include <memory>

#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

std::unique_ptr<ViewRenderer> makeCpuRenderer(const PatternSpec& spec, const FilterOptions& options);

}  // namespace stochtex
