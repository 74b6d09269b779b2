#pragma once
// The prefiltered colormap H̄(μ, σ_x, σ_y) = [H ∗ G(0, diag(σ_x², σ_y²))](μ)
// with clamp-to-edge (paper eq. 5–6, §5): for a footprint whose noise values
// have mean μ and standard deviations σ, the filtered colour is one lookup.
//
// Two modes:
//   paper  — σ levels 2^k/256, k = 0..5 (36 tables), bilinear in μ, nearest
//            σ level (in log2), exactly as in section 5;
//   smooth — σ levels 0 and 2^k/256, k = 0..8 (up to σ = 1, where the blur has
//            flattened H), interpolated between σ levels (linearly in σ below
//            1/256, in log2 σ above), so nothing pops when σ̂ changes.
// Layers blurred widely along an axis keep fewer entries along it, halved
// while σ spans at least 4 of their spacings: memory, build time and the
// cache lines a lookup reads stay low, and a bilinear read between kept
// entries is within 0.0019 of the exact blur per axis and per unit of edge
// height in the table (h²/8 · |f''| at h = σ/4; checked against direct
// convolution in the tests).
//
// An axis whose input is a field bounded in [0, 1] (another table's output,
// in a texture graph) is prefiltered with the Beta distribution of the
// input's mean and variance instead of the Gaussian: its layers are levels
// of the Beta's shape (kernel betaLevelCoordinate), at the same level values.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "stochtex/core/enum_names.h"
#include "stochtex/pattern/colormap.h"

namespace stochtex {

struct LayerTapsLanes;  // noise/tiling_blending_lanes.h

// The largest table the filtered modes prefilter: a layer costs ~R² per pair
// of σ levels (100 pairs in smooth mode); R = 1024 takes ~1.4 s and 0.5 GB,
// and each doubling four times that.
constexpr int kMaxPrefilteredResolution = 1024;
// The most memory a prefiltered table's layers may take: a 1024² table
// with one Beta axis (640 MiB; Gaussian axes 256 MiB), not one with two (a
// Beta axis keeps every entry of every layer: 1600 MiB at 1024²).
constexpr size_t kMaxPrefilteredBytes = size_t(1) << 30;
// Fails (parameter "resolution") unless both sides are at most kMaxPrefilteredResolution.
void validatePrefilteredResolution(int width, int height);

enum class PrefilterMode { Paper, Smooth };
inline const EnumNames<PrefilterMode> kPrefilterModeNames{{"paper", PrefilterMode::Paper},
                                                          {"smooth", PrefilterMode::Smooth}};

// Which axes (x, y) of a table are Beta axes (see above).
using BetaAxes = std::array<bool, 2>;

class PrefilteredColormap {
public:
    PrefilteredColormap() = default;
    // Moves only: layerTexels_ points into the layers' own entries.
    PrefilteredColormap(const PrefilteredColormap&) = delete;
    PrefilteredColormap& operator=(const PrefilteredColormap&) = delete;
    PrefilteredColormap(PrefilteredColormap&&) = default;
    PrefilteredColormap& operator=(PrefilteredColormap&&) = default;
    PrefilteredColormap(const ColormapTable& h, PrefilterMode mode, BetaAxes beta = {false, false});

    PrefilterMode mode() const { return mode_; }
    const BetaAxes& betaAxes() const { return beta_; }
    // The σ levels of a Gaussian axis; sigmas().size() levels per axis.
    const std::vector<double>& sigmas() const { return sigmas_; }
    // The levels of axis 0 (x) or 1 (y): σ, or τ on a Beta axis.
    const std::vector<double>& axisLevels(int axis) const { return beta_[size_t(axis)] ? betaLevels_ : sigmas_; }
    const ColormapTable& layer(int kx, int ky) const { return layers_[size_t(kx) * sigmas_.size() + size_t(ky)]; }

    // The table at mean (mx, my) and deviations (sx, sy): [H ∗ G_σ](μ) on
    // Gaussian axes, E[H] under the Beta of (m, σ²) on Beta axes.
    Rgb sample(float mx, float my, float sx, float sy) const;
    // sample at count pixels (mx[k], my[k], sx[k], sy[k]) into rgb[3k..3k+2]:
    // each pixel's layers and taps are found a few pixels ahead of its
    // blend and their entries prefetched meanwhile (a lookup reads up to
    // four layers of up to a megabyte each, beyond a core's L2, and
    // otherwise waits on memory one pixel at a time). On Gaussian axes
    // they are found in SIMD lanes (layerTapsLanes: the smooth mode's level
    // weights within a few ulps of sample's, the rest the same values).
    // Returns how many lookups the lanes found (the rest: one at a time).
    size_t sampleRow(const float* mx, const float* my, const float* sx, const float* sy, float* rgb,
                     size_t count) const;

    // sampleRow where every deviation is 0 (a zoom at one texel per pixel:
    // level 0 holds no within-texel variance): layer (0, 0) alone, the
    // level a σ of 0 reads in every mode (the smooth mode's σ = 0, the
    // paper's finest, 1/256, which smaller σ clamp to), its taps in lanes as
    // an unfiltered lookup's (ColormapTable::sampleRow). Returns how many
    // the lanes tapped.
    size_t sampleRowWithoutDeviations(const float* mx, const float* my, float* rgb, size_t count) const {
        return layer(0, 0).sampleRow(mx, my, 1, rgb, count);
    }

    // Every layer resampled to rx × ry entries (layers stored coarser are
    // smooth, so their bilinear resampling is far below a colour step),
    // stacked: layer kx·n + ky in rows [k·ry, (k+1)·ry), row j = y of j/(ry−1).
    // The GPU texture array and the engine export are made from it.
    Image atlas(int rx, int ry) const;

    size_t bytes() const;
    // What bytes() will be for a width × height table, before building it
    // (the constructor refuses a table above kMaxPrefilteredBytes).
    static size_t layerBytes(int width, int height, PrefilterMode mode, BetaAxes beta);

    // σ levels of a mode, in colormap-domain units.
    static std::vector<double> sigmaLevels(PrefilterMode mode);
    // τ levels of a Beta axis (kernel betaLevelCoordinate): as many.
    static std::vector<double> betaLevels(PrefilterMode mode);

private:
    // A lookup in two steps (sample = blend ∘ find), so sampleRow can fetch
    // ahead: its layers (one when it falls on a level, f = 0), their taps
    // and the layers' weights.
    struct Lookup {
        std::array<const ColormapTable*, 4> layers;
        std::array<ColormapTable::Taps, 4> taps;
        kernel::vec2 f;
        bool single;
    };
    Lookup find(float mx, float my, float sx, float sy) const;
    Rgb blend(const Lookup& l) const;
    // sampleRow's two ways along a row: the lanes' lookups, and one pixel at a time.
    void blendFound(const LayerTapsLanes& found, size_t count, float* rgb) const;
    void lookupRow(const float* mx, const float* my, const float* sx, const float* sy, float* rgb, size_t count) const;

    PrefilterMode mode_ = PrefilterMode::Paper;
    BetaAxes beta_{false, false};
    std::vector<double> sigmas_, betaLevels_;
    std::vector<ColormapTable> layers_;
    // The entries along x of the layers (kx, ·) and along y of (·, ky): a
    // layer's size along an axis depends on that axis's level only.
    std::vector<int32_t> widths_, heights_;
    // Each layer's entries, as layer(kx, ky) at kx·n + ky: a lookup in lanes
    // reads four layers' without going through their tables.
    std::vector<const ColormapTable::Texel*> layerTexels_;
};

// Reference for tests: [H ∗ G_σ](μ) for the bilinear table H with clamp-to-edge
// by numerical integration (Simpson-free Riemann sum over ±6σ, `steps` per axis).
Rgb convolveColormapNumerically(const ColormapTable& h, double mx, double my, double sx, double sy, int steps = 400);
// Reference for tests: E[H(X, y)] along x for X ~ Beta of mean mx and
// deviation sx (var ≤ mx(1 − mx)), y = my, by the midpoint rule over the
// Beta's quantiles (`steps` of them): a route independent of the tables'.
Rgb betaAverageNumerically(const ColormapTable& h, double mx, double my, double sx, int steps = 20000);

}  // namespace stochtex
