#pragma once
// A noise vector field of K channels tiled and blended on one triangle grid
// (paper eq. 7 per channel). Each channel is an example with the seed of its
// tile offsets. Channels that must see the same tiles — a colour pair whose
// covariance is filtered, a quadrature pair (phasor noise), a slope pair
// (LEAN mapping) — are declared Shared: they then must have one seed, and
// only then can covariances between channels be estimated (eq. 16–19).
// Independent channels may happen to share a seed; nothing relies on it.
#include <vector>

#include "stochtex/noise/tiling_blending.h"

namespace stochtex {

enum class OffsetSharing { Independent, Shared };

class TiledField {
public:
    TiledField() = default;
    // InputError naming the parameter: `channels` (none, or examples of
    // different sizes), `offsets` (Shared with different seeds),
    // `gridDensity` (a density not finite and positive).
    TiledField(std::vector<TilingBlendingNoise> channels, const GridLayout& grid, OffsetSharing sharing);

    int channelCount() const { return int(channels_.size()); }
    const TilingBlendingNoise& channel(int k) const { return channels_[size_t(k)]; }
    const GridLayout& grid() const { return grid_; }
    OffsetSharing sharing() const { return sharing_; }
    bool shared() const { return sharing_ == OffsetSharing::Shared; }
    int exampleSize() const { return channels_.front().example().size(); }

private:
    std::vector<TilingBlendingNoise> channels_;
    GridLayout grid_;
    OffsetSharing sharing_ = OffsetSharing::Independent;
};

}  // namespace stochtex
