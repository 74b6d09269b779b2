#pragma once
// A pattern beside what makes it: the colormap H, H shaded by where N falls,
// and the two tiled noises (the gallery's and the paper-figure sheets).
#include <string>

#include "stochtex/image/image.h"
#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

struct PatternSheet {
    Image pattern;  // size × size, the view at `scale` texels per pixel (linear light)
    // A program whose output is a colormap of two leaves (every plain
    // pattern, a graph whose linear part feeds its colormap): pattern | H,
    // H where N falls / N_x, N_y (2·size × size), in sRGB codes; a file with
    // a normal map shows its LEAN shading (its lean program, unfiltered, lit
    // as its normal_map says, seen from above) right of the colours (3·size
    // wide). Any other graph: its stages (graphSheet).
    Image sheet;
};
// The file's program (GraphPattern::build) and what makes it.
PatternSheet patternSheet(const PatternSpec& file, double scale, int size, const std::string& label);

// A graph evaluated per pixel (graph_pattern.h) and its stages: each leaf
// and operation node over the same region at half the side (fields as
// gray), in the program's order, the last being the pattern, captioned
// "id (type)".
PatternSheet graphSheet(const GraphPattern& graph, const TextureGraph& nodes, double scale, int size);

}  // namespace stochtex
