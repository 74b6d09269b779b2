#pragma once
// The CPU evaluator of a pattern file as a ViewRenderer that owns what it
// reads: the file's program under the options' response (GraphPattern::build:
// a graph's, a plain pattern's "two leaves → colormap", or its normal map's
// lean) filtered by FilteredGraph. With `parts`, every part built before
// from the same inputs is taken from it and the new ones kept there
// (PartCache): a command that builds several programs of one file — the
// PBR set's responses, a tileable view's period found first — synthesises
// its examples and builds its pyramids once.
#include <memory>

#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

class PartCache;  // pattern/part_cache.h

std::unique_ptr<ViewRenderer> makeCpuRenderer(const PatternSpec& spec, const FilterOptions& options,
                                              PartCache* parts = nullptr);

}  // namespace stochtex
