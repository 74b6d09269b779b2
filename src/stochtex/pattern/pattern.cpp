#include "stochtex/pattern/pattern.h"

#include <cmath>
#include <memory>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/core/parallel.h"
#include "stochtex/pattern/texture_graph.h"

namespace stochtex {

Pattern Pattern::build(const PatternSpec& spec) {
    std::array<NoiseExample, 2> examples;
    if (spec.graph) {
        if (!foldsIntoPattern(*spec.graph))
            throw InputError(spec.name + ": this graph has a non-linear node before its output (\"" + spec.graph->output +
                             "\" reads one), so it is not the pattern H∘N of two fields this needs; such graphs are "
                             "evaluated per pixel, where docs/GRAPHS.md lists");
        GraphFields fields = buildGraphFields(*spec.graph, spec.seed, spec.name);
        const uint32_t sx = deriveSeed(spec.seed, 1);
        const uint32_t sy = spec.offsets == OffsetMode::Shared ? sx : deriveSeed(spec.seed, 2);
        return Pattern(std::move(fields.examples), {sx, sy}, buildColormap(fields.colormap), spec.gridDensity,
                       spec.offsets == OffsetMode::Shared ? OffsetSharing::Shared : OffsetSharing::Independent);
    }
    for (int axis = 0; axis < 2; ++axis) {
        NoiseSpec ns = spec.noise[axis];
        ns.spectrum.seed = noiseSeed(spec, axis);
        examples[size_t(axis)] = buildNoiseExample(ns, axis == 0 ? spec.name + ": noise_x" : spec.name + ": noise_y");
    }
    if (examples[0].size() != examples[1].size())
        throw InputError(spec.name + ": noise_x is " + std::to_string(examples[0].size()) + " texels wide but noise_y is " +
                         std::to_string(examples[1].size()) + "; both examples must have the same size");
    const uint32_t sx = deriveSeed(spec.seed, 1);
    const uint32_t sy = spec.offsets == OffsetMode::Shared ? sx : deriveSeed(spec.seed, 2);
    return Pattern(std::move(examples), {sx, sy}, buildColormap(spec.colormap), spec.gridDensity,
                   spec.offsets == OffsetMode::Shared ? OffsetSharing::Shared : OffsetSharing::Independent);
}

Pattern::Pattern(std::array<NoiseExample, 2> examples, std::array<uint32_t, 2> offsetSeeds, ColormapTable colormap,
                 double gridDensity, OffsetSharing sharing)
    : colormap_(std::move(colormap)) {
    std::vector<TilingBlendingNoise> noises;
    for (size_t a = 0; a < 2; ++a)
        noises.emplace_back(std::make_shared<const NoiseExample>(std::move(examples[a])), offsetSeeds[a]);
    field_ = TiledField(std::move(noises), gridDensity, sharing);
}

std::array<float, 2> Pattern::field(double u, double v) const {
    const BlendStencil s = triangleGrid(u, v, gridDensity());
    const float fu = periodFraction(u), fv = periodFraction(v);
    return {example(0).toOutput(noise(0).blend(s, fu, fv)), example(1).toOutput(noise(1).blend(s, fu, fv))};
}

Rgb Pattern::evaluate(double u, double v) const {
    const auto n = field(u, v);
    return colormap_.sample(n[0], n[1]);
}

// Walks the view's pixels row-parallel. Neighbouring pixels on a scanline
// mostly see the same three tiles, so the per-tile work (hashing the offsets,
// locating the rows to read) is redone only when the tiles change.
template <class PixelFn>
void Pattern::forEachPixel(const View& view, PixelFn&& fn) const {
    const double invW = 1.0 / double(exampleSize());
    const TilingBlendingNoise &nx = noise(0), &ny = noise(1);
    parallelRows(view.height, [&](int y0, int y1) {
        PixelTiles tiles;
        for (int py = y0; py < y1; ++py) {
            bool valid = false;
            const double v = pixelUv(view, invW, 0, py)[1];
            const float fv = periodFraction(v);
            const TriangleGridRow grid(v, gridDensity());
            for (int px = 0; px < view.width; ++px) {
                const double u = pixelUv(view, invW, px, py)[0];
                const BlendStencil s = grid.stencil(u);
                if (!valid || !sameTiles(s, tiles.stencil)) {
                    tiles.tiles[0] = nx.tileRows(s, fv);
                    tiles.tiles[1] = ny.tileRows(s, fv);
                    valid = true;
                }
                tiles.stencil = s;
                fn(px, py, tiles, periodFraction(u));
            }
        }
    });
}

Image Pattern::render(const View& view) const {
    validateView(view);
    Image out(view.width, view.height, 3, Image::Uninitialized{});
    const TilingBlendingNoise &noiseX = noise(0), &noiseY = noise(1);
    const NoiseExample &exampleX = example(0), &exampleY = example(1);
    forEachPixel(view, [&](int px, int py, const PixelTiles& t, float fu) {
        const float nx = exampleX.toOutput(noiseX.blend(t.stencil, t.tiles[0], fu));
        const float ny = exampleY.toOutput(noiseY.blend(t.stencil, t.tiles[1], fu));
        const Rgb c = colormap_.sample(nx, ny);
        float* __restrict p = out.row(py) + size_t(px) * 3;
        p[0] = c[0];
        p[1] = c[1];
        p[2] = c[2];
    });
    return out;
}

Image Pattern::renderNoise(int axis, const View& view) const {
    validateView(view);
    Image out(view.width, view.height, 1, Image::Uninitialized{});
    const TilingBlendingNoise& channel = noise(axis);
    const NoiseExample& e = example(axis);
    forEachPixel(view, [&](int px, int py, const PixelTiles& t, float fu) {
        const float n = e.toOutput(channel.blend(t.stencil, t.tiles[size_t(axis)], fu));
        out.at(px, py) = std::min(std::max(n, 0.0f), 1.0f);
    });
    return out;
}

}  // namespace stochtex
