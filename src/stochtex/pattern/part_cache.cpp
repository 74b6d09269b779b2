#include "stochtex/pattern/part_cache.h"

#include <algorithm>

#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

namespace {

// How each part is built: by the cache on a miss, and where there is no cache.
std::shared_ptr<const ColormapTable> makeColormap(const ColormapSpec& spec) {
    return std::make_shared<const ColormapTable>(buildColormap(spec));
}
std::shared_ptr<const FootprintEstimator> makeEstimator(const TiledField& field, bool covariance, bool pack8) {
    return std::make_shared<const FootprintEstimator>(field, covariance, pack8);
}
std::shared_ptr<const PrefilteredColormap> makePrefiltered(const ColormapTable& blended, PrefilterMode mode,
                                                           BetaAxes beta) {
    return std::make_shared<const PrefilteredColormap>(blended, mode, beta);
}

}  // namespace

template <class Key, class Value, class Build>
Value PartCache::find(Entries<Key, Value>& entries, const Key& key, int& count, Build&& build) {
    for (Entry<Key, Value>& e : entries)
        if (e.key == key) {
            e.used = generation_;
            return e.value;
        }
    Value value = build();  // may throw: nothing is kept
    entries.push_back({key, value, generation_});
    ++count;
    return value;
}

PartCache::Field PartCache::field(const FieldKey& key, const std::function<Field()>& build) {
    return find(fields_, key, builds_.fields, build);
}

TiledField PartCache::slopes(const std::shared_ptr<const NoiseExample>& height, double amplitude, uint32_t seed,
                             const GridLayout& grid, const std::function<TiledField()>& build) {
    return find(slopes_, SlopeKey{height, amplitude, seed, grid}, builds_.slopes, build);
}

std::shared_ptr<const ColormapTable> PartCache::colormap(const ColormapSpec& spec) {
    return find(colormaps_, spec, builds_.colormaps, [&] { return makeColormap(spec); });
}

std::shared_ptr<const FootprintEstimator> PartCache::estimator(const TiledField& field, bool covariance, bool pack8) {
    EstimatorKey key{{}, {}, field.grid(), field.sharing(), covariance, pack8};
    for (int k = 0; k < field.channelCount(); ++k) {
        key.examples.push_back(field.channel(k).sharedExample());
        key.seeds.push_back(field.channel(k).offsetSeed());
    }
    return find(estimators_, key, builds_.estimators, [&] { return makeEstimator(field, covariance, pack8); });
}

std::shared_ptr<const PrefilteredColormap> PartCache::prefiltered(const ColormapTable& blended, PrefilterMode mode,
                                                                  BetaAxes beta) {
    return find(prefiltered_, PrefilteredKey{blended, mode, beta}, builds_.prefiltered,
                [&] { return makePrefiltered(blended, mode, beta); });
}

std::shared_ptr<void> PartCache::attachment(const std::shared_ptr<const void>& part, const std::string& what,
                                            const std::function<std::shared_ptr<void>()>& make) {
    return find(attachments_, AttachmentKey{part, what}, builds_.attachments, make);
}

void PartCache::beginGeneration() {
    ++generation_;
    const auto drop = [&](auto& entries) {
        std::erase_if(entries, [&](const auto& e) { return e.used + 2 < generation_; });
    };
    drop(attachments_);
    drop(estimators_);
    drop(slopes_);
    drop(prefiltered_);
    drop(colormaps_);
    drop(fields_);
}

void PartCache::clear() {
    attachments_.clear();
    estimators_.clear();
    slopes_.clear();
    prefiltered_.clear();
    colormaps_.clear();
    fields_.clear();
}

size_t PartCache::size() const {
    return fields_.size() + slopes_.size() + colormaps_.size() + estimators_.size() + prefiltered_.size() +
           attachments_.size();
}

TiledField slopesPart(PartCache* parts, const std::shared_ptr<const NoiseExample>& height, double amplitude,
                      uint32_t seed, const GridLayout& grid, const std::function<TiledField()>& build) {
    return parts ? parts->slopes(height, amplitude, seed, grid, build) : build();
}

std::shared_ptr<const ColormapTable> colormapPart(PartCache* parts, const ColormapSpec& spec) {
    return parts ? parts->colormap(spec) : makeColormap(spec);
}

std::shared_ptr<const FootprintEstimator> estimatorPart(PartCache* parts, const TiledField& field, bool covariance,
                                                        bool pack8) {
    return parts ? parts->estimator(field, covariance, pack8) : makeEstimator(field, covariance, pack8);
}

std::shared_ptr<const PrefilteredColormap> prefilteredPart(PartCache* parts, const ColormapTable& blended,
                                                           PrefilterMode mode, BetaAxes beta) {
    return parts ? parts->prefiltered(blended, mode, beta) : makePrefiltered(blended, mode, beta);
}

}  // namespace stochtex
