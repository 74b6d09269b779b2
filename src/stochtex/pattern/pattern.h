#pragma once
// A colour-mapped noise vector field S = H ∘ N (paper eq. 1–2), ready to
// evaluate: two tiled-and-blended noises N = (N_x, N_y) over a shared
// triangle grid, and a colormap table H. A file's normal map is not here:
// under the lean response the file is its program (GraphPattern::build).
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "stochtex/image/image.h"
#include "stochtex/noise/example.h"
#include "stochtex/noise/tiled_field.h"
#include "stochtex/noise/tiling_blending.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

class Pattern {
public:
    static Pattern build(const PatternSpec& spec);
    // sharing Shared: both noises see the same tiles (one seed; InputError
    // `offsets` otherwise), e.g. a quadrature pair.
    Pattern(std::array<NoiseExample, 2> examples, std::array<uint32_t, 2> offsetSeeds, ColormapTable colormap,
            double gridDensity, OffsetSharing sharing);


    // N(uv) in output space (after T⁻¹ for Gaussianized exemplars).
    std::array<float, 2> field(double u, double v) const;
    // S(uv) = H(N(uv)).
    Rgb evaluate(double u, double v) const;

    // Unfiltered rendering, one sample per pixel centre, multi-threaded.
    Image render(const View& view) const;
    // N_axis as a gray image (axis 0 = x, 1 = y), same view mapping.
    Image renderNoise(int axis, const View& view) const;

    // N as a two-channel tiled field (channel 0 = N_x, 1 = N_y), with its
    // declared offset sharing: the one place the noises are held.
    const TiledField& tiledField() const { return field_; }
    const TilingBlendingNoise& noise(int axis) const { return field_.channel(axis); }
    const NoiseExample& example(int axis) const { return noise(axis).example(); }
    const ColormapTable& colormap() const { return colormap_; }
    int exampleSize() const { return field_.exampleSize(); }
    bool sharedOffsets() const { return field_.shared(); }
    double gridDensity() const { return field_.gridDensity(); }

private:
    struct PixelTiles {
        BlendStencil stencil;
        std::array<TilingBlendingNoise::TileRows, 2> tiles;
    };
    template <class PixelFn>
    void forEachPixel(const View& view, PixelFn&& fn) const;

    TiledField field_;
    ColormapTable colormap_;
};


}  // namespace stochtex
