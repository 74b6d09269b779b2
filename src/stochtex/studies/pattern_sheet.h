#pragma once
// A pattern beside what makes it: the colormap H, H shaded by where N falls,
// and the two tiled noises (the gallery's and the paper-figure sheets).
#include <string>

#include "stochtex/image/image.h"
#include "stochtex/pattern/pattern.h"

namespace stochtex {

struct PatternSheet {
    Image pattern;  // size × size, the view at `scale` texels per pixel (linear light)
    Image sheet;    // pattern | H, H where N falls / N_x, N_y (2·size × size), in sRGB codes
};
PatternSheet patternSheet(const Pattern& pattern, double scale, int size, const std::string& label);

}  // namespace stochtex
