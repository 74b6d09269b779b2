#pragma once
// The parts a pattern's program is built from — its fields' examples, a lean
// node's slope fields, its colormaps' tables, its estimators' pyramids, its
// prefiltered tables, and what a device made of them (the GPU view's
// textures) — kept by what each is built
// from, so that building the program again after an edit remakes only the
// parts the edit changed: a colormap edit synthesises no noise and builds no
// pyramid, a noise edit rasterises and prefilters no table (issue 31, the
// workbench's edits). GraphPattern::build, FilteredGraph and the GPU view
// take one where the caller keeps it; without one every part is built.
//
// A part's key is what it is built from: a field, the graph nodes it folds
// (compared by value) with the pattern seed; a colormap table, its spec; a
// prefiltered table, the blended table's entries and the mode; a slope
// field, an estimator or a device's copy, the kept parts they are made of
// (held, so compared by identity without reuse of a freed address). A part built from
// equal inputs is the same part, so a build with the cache renders what one
// without it does, bit for bit (tested).
//
// Memory: a part that no build used in the last two generations is dropped
// when the next begins (the workbench begins one per document revision), so
// after a build the parts of at most three revisions are kept — its own and
// the two before, so that an undo, or a redo after it, rebuilds nothing.
// Not thread-safe: one build at a time. A device's attachments belong to the
// context that made them: one GL context (or contexts sharing objects) per
// cache.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stochtex/filter/footprint_stats.h"
#include "stochtex/noise/example.h"
#include "stochtex/noise/tiled_field.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/node_info.h"
#include "stochtex/pattern/pattern_file.h"
#include "stochtex/pattern/prefiltered_colormap.h"

namespace stochtex {

class PartCache {
public:
    // A field's key: the nodes it folds (itself and every node upstream, in
    // id order), the pattern seed they derive their seeds from, and the
    // context its errors are worded in.
    struct FieldKey {
        std::vector<GraphNode> nodes;
        uint32_t patternSeed = 0;
        std::string context;
        bool operator==(const FieldKey&) const = default;
    };
    // A field with the texels each of its nodes' examples holds (the graph's
    // example budget counts them as building them would).
    struct Field {
        std::shared_ptr<const NoiseExample> example;
        std::vector<std::pair<std::string, long long>> texels;
    };

    // Each part by its key: the kept one, or `build`'s result, kept. What
    // `build` throws passes through and nothing is kept.
    Field field(const FieldKey& key, const std::function<Field()>& build);
    TiledField slopes(const std::shared_ptr<const NoiseExample>& height, double amplitude, uint32_t seed,
                      const GridLayout& grid, const std::function<TiledField()>& build);
    std::shared_ptr<const ColormapTable> colormap(const ColormapSpec& spec);
    std::shared_ptr<const FootprintEstimator> estimator(const TiledField& field, bool covariance, bool pack8);
    std::shared_ptr<const PrefilteredColormap> prefiltered(const ColormapTable& blended, PrefilterMode mode,
                                                           BetaAxes beta);
    // What a device makes of a kept part (the GPU view: the texture of an
    // example, a pyramid, an atlas), named `what`, kept as the parts are:
    // an edit uploads only the parts it changed. The value is the device's
    // type (this module knows none); it is destroyed when dropped, so the
    // cache is cleared or destroyed while the device's context is current.
    std::shared_ptr<void> attachment(const std::shared_ptr<const void>& part, const std::string& what,
                                     const std::function<std::shared_ptr<void>()>& make);

    // Starts a generation: drops the parts no build used in the last two.
    void beginGeneration();
    // Drops every part (after a reload: the files the specs name may have changed).
    void clear();
    // How many parts of each kind were built (not found) so far: what an edit rebuilt.
    struct Builds {
        int fields = 0, slopes = 0, colormaps = 0, estimators = 0, prefiltered = 0, attachments = 0;
    };
    const Builds& builds() const { return builds_; }
    size_t size() const;  // parts kept

private:
    template <class Key, class Value>
    struct Entry {
        Key key;
        Value value;
        uint64_t used = 0;  // the last generation that used it
    };
    template <class Key, class Value>
    using Entries = std::vector<Entry<Key, Value>>;
    struct EstimatorKey {
        std::vector<std::shared_ptr<const NoiseExample>> examples;
        std::vector<uint32_t> seeds;
        GridLayout grid;
        OffsetSharing sharing = OffsetSharing::Independent;
        bool covariance = false, pack8 = false;
        bool operator==(const EstimatorKey&) const = default;
    };
    struct SlopeKey {
        std::shared_ptr<const NoiseExample> height;
        double amplitude = 0;
        uint32_t seed = 0;
        GridLayout grid;
        bool operator==(const SlopeKey&) const = default;
    };
    struct PrefilteredKey {
        ColormapTable blended;
        PrefilterMode mode = PrefilterMode::Paper;
        BetaAxes beta{false, false};
        bool operator==(const PrefilteredKey&) const = default;
    };
    struct AttachmentKey {
        std::shared_ptr<const void> part;
        std::string what;
        bool operator==(const AttachmentKey&) const = default;
    };
    // The kept value for `key`, or `build`'s, kept; `count` counts builds.
    template <class Key, class Value, class Build>
    Value find(Entries<Key, Value>& entries, const Key& key, int& count, Build&& build);

    uint64_t generation_ = 1;
    Builds builds_;
    Entries<FieldKey, Field> fields_;
    Entries<SlopeKey, TiledField> slopes_;
    Entries<ColormapSpec, std::shared_ptr<const ColormapTable>> colormaps_;
    Entries<EstimatorKey, std::shared_ptr<const FootprintEstimator>> estimators_;
    Entries<PrefilteredKey, std::shared_ptr<const PrefilteredColormap>> prefiltered_;
    Entries<AttachmentKey, std::shared_ptr<void>> attachments_;
};

// A part from `parts`, or built now where there is none (a build that keeps
// nothing): callers that may run either way ask through these, so that how
// each part is built is written once (part_cache.cpp).
TiledField slopesPart(PartCache* parts, const std::shared_ptr<const NoiseExample>& height, double amplitude,
                      uint32_t seed, const GridLayout& grid, const std::function<TiledField()>& build);
std::shared_ptr<const ColormapTable> colormapPart(PartCache* parts, const ColormapSpec& spec);
std::shared_ptr<const FootprintEstimator> estimatorPart(PartCache* parts, const TiledField& field, bool covariance,
                                                        bool pack8);
std::shared_ptr<const PrefilteredColormap> prefilteredPart(PartCache* parts, const ColormapTable& blended,
                                                           PrefilterMode mode, BetaAxes beta = {false, false});

}  // namespace stochtex
