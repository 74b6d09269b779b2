#pragma once
// What the workbench shows of a plain pattern beside the picture — its
// colormap table and its two examples with their power spectra — built from
// the document's spec, each part again only when its own spec changed: a
// colormap edit does not synthesise the noises again, a noise edit does not
// rasterise the colormap.
#include <array>
#include <optional>

#include "stochtex/image/image.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex {

class PartCache;  // pattern/part_cache.h

struct PatternPreviews {
    Image colormap;                 // the table with y = 1 in the top row, encoded for display
    std::array<Image, 2> examples;  // N_x, N_y (empty: a graph's, or N_y of a quadrature pair)
    std::array<Image, 2> spectra;   // their power spectra, for display
};

class PreviewCache {
public:
    // The previews of `spec`, each part kept from the last call where its
    // spec is equal (InputError as building the part words it); with
    // `parts`, the colormap's table is the one the program is built with.
    const PatternPreviews& update(const PatternSpec& spec, PartCache* parts = nullptr);
    const PatternPreviews& previews() const { return previews_; }
    // Forgets every part: after a reload, the files the specs name may have changed.
    void clear();
    // Parts built so far: what an edit rebuilt (the tests').
    int colormapBuilds() const { return colormapBuilds_; }
    int exampleBuilds() const { return exampleBuilds_; }

private:
    PatternPreviews previews_;
    std::optional<ColormapSpec> colormapKey_;
    std::array<std::optional<NoiseSpec>, 2> noiseKeys_;  // nullopt: none built (or none to build)
    int colormapBuilds_ = 0, exampleBuilds_ = 0;
};

}  // namespace stochtex
