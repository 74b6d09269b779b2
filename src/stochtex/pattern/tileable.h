#pragma once
// Tileable renders: a view that is exactly one period of its pattern, so
// that the image wraps without a seam (a texture an engine repeats).
//
// The field is made periodic, not the image blended: the image covers a
// whole number of example periods along each axis (the examples repeat
// with them), and the triangle grid is stretched along u to repeat over
// them too (GridLayout::periodic; the v density is kept, the u density
// moves to the nearest whole number of cells), its vertices taken modulo
// the period, so the tiles' random offsets repeat as well. The cost: the
// image repeats (its period is the image), and the grid's triangles are
// stretched by `stretch` along u.
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/pattern_file.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

class PartCache;  // pattern/part_cache.h

struct TilePeriod {
    int periodsU = 0, periodsV = 0;  // example periods across the view
    int exampleSize = 0;             // W, texels per period
    double stretch = 1;              // the grid's u density over the plane's
};

// Makes `view` one period of `spec` under `response`: its scale is set so
// that its width covers the nearest whole number of example periods (at
// least 1) to what it covered, and spec.gridPeriods to those periods. The
// height must then cover a whole number too (InputError naming size
// otherwise: e.g. a square view always does). InputError naming
// gridPeriods for a program that transforms a leaf's uv. It builds the
// program to learn its example size: with `parts` (PartCache), the render
// that follows takes the examples built here instead of building them again.
TilePeriod makeTileable(PatternSpec& spec, const ResponseOptions& response, View& view, PartCache* parts = nullptr);

}  // namespace stochtex
