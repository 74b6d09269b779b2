#pragma once
// Any texture graph, evaluated per pixel (issue "Texture graphs", paper
// Figure 14 and §7): the linear part folds into the examples of the graph's
// leaves — the linear field nodes that a non-linear node reads — tiled and
// blended on one triangle grid; the non-linear nodes (colormap,
// colormap_field, curve, product, mix, compose, lean, and affine or sum over
// their results) run as a short program of ops (ops/ops.h) on the leaves'
// values.
// A lean node reads its height's slopes (spectral, as a derivative node's)
// as two more leaves on the height's tiles, and their covariance.
//
// Filtering (FilteredGraph) goes beyond the paper, which filters one
// transfer function of Gaussian fields: a non-linear node's output is not
// Gaussian, so it is carried by its footprint moments. The leaves' moments
// come from the estimators (or the exact footprint statistics); a table
// node's output field g has E[g] and E[g²] from one lookup of the
// prefiltered table of (g, g²) at the moments of its inputs, and is then
// treated as Gaussian with that mean and variance by the next table (moment
// matching); the last colormap is the paper's H̄(μ, σ). The reference is
// the supersampled average of the point evaluation. The
// approximation's error against it is measured by `reproduce figure14`
// (docs/GRAPHS.md, docs/MATH.md "Filtering a graph by moment matching").
//
// A plain pattern file {noise_x, noise_y, colormap} is the program "two
// leaves → colormap" (paper eq. 1–2): its leaves get the pattern's
// tile-offset seeds and its colormap op is H̄(μ̂, σ̂). A graph whose colormap
// reads two linear fields with examples of one size under no transform
// folds to the same program, and both run at the plain speed
// (plainColormap()).
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "stochtex/core/progress.h"
#include "stochtex/filter/footprint_stats.h"
#include "stochtex/pattern/camera.h"
#include "stochtex/pattern/colormap.h"
#include "stochtex/pattern/filter_options.h"
#include "stochtex/pattern/ops/ops.h"
#include "stochtex/pattern/pattern_spec.h"
#include "stochtex/pattern/prefiltered_colormap.h"
#include "stochtex/pattern/texture_graph.h"
#include "stochtex/pattern/view.h"
#include "stochtex/pattern/view_renderer.h"

namespace stochtex {

class PartCache;  // pattern/part_cache.h

// The examples' tables hold at most this many entries in all: one colormap
// at the largest resolution (kMaxColormapResolution², as a plain pattern's
// may be). Each table is kept twice, for points and in blending space, 16
// bytes an entry: 512 MiB.
constexpr long long kMaxGraphTableEntries = 1ll << 24;
static_assert(kMaxGraphTableEntries >= (long long)kMaxColormapResolution * kMaxColormapResolution);
// The op evaluations that tabulating a graph's functions of sources may
// take in all (GraphPattern::planSourceFunctions): about a second at ~45 ns
// each on the 2-core VM, e.g. 64 two-source tables of 256² over four ops.
constexpr long long kMaxFunctionWork = 1ll << 24;

class GraphPattern {
public:
    // A unit direction in the texture frame (x along u, y along v, z up).
    using Direction = std::array<float, 3>;
    static constexpr Direction kFromAbove{0.0f, 0.0f, 1.0f};

    // Any pattern file: a graph's, or a plain pattern's {noise_x, noise_y,
    // colormap} as the program "two leaves → colormap", or under the lean
    // response its normal map's "height's slopes, albedo → lean" (the
    // response's covariance switch is the lean node's). The one place a
    // response picks a program: InputError `response` for lean on a graph
    // (its lean nodes shade it) or on a plain pattern without a normal map,
    // InputError naming the node for what only building shows (a linear
    // node over a non-linear field, a Gaussianized exemplar read other than
    // by a table, an output that reads no field).
    // With `parts`, the parts of the program built before from the same
    // inputs are taken from it, and the new ones kept there (PartCache).
    static GraphPattern build(const PatternSpec& spec, const ResponseOptions& response = {},
                              PartCache* parts = nullptr);

    // One operation of the per-pixel program: an op (ops/ops.h) on slots.
    // Slots 0..leafCount()−1 hold the leaves; operation k writes slot
    // leafCount() + k.
    struct Operation {
        std::string id;                         // the node
        const NodeInfo* info = nullptr;         // its type
        std::array<int, 3> inputs{-1, -1, -1};  // slots, in the node's port order (lean: its slopes, then the albedo)
        int table = -1;                         // the op's table in tables(), −1: none
        // The leaf pair whose covariance the op reads filtered (OpContext::
        // slopeCov): its first input's pair, when that pair estimates its
        // covariance (a lean op's slopes); −1: none (slopeCov = 0). Decided
        // here once for the CPU evaluator and the GLSL emitter.
        int covariancePair = -1;
        OpParams params;  // the op and its typed parameters
        // Filtered, this op as a function F of its sources (planSourceFunctions):
        // a colormap op (a colour) or a colormap_field op (a field) over a
        // table of F, read at its one or two source slots (one: twice).
        // Absent: the op itself.
        struct SourceFunction {
            OpParams params;
            std::array<int, 3> inputs{-1, -1, -1};
            int table = -1;
        };
        std::optional<SourceFunction> sourceFunction;
        // Whether the filtered program reads this op's value when it matches
        // moments: false where only functions of sources read past it (it
        // need not run there).
        bool filteredRead = true;
    };
    using Table = OpTable;
    // What a filtered program calls for an operation: the op, or the
    // function of its sources standing in for it (moment matching only:
    // MeanOnly passes on means through the ops themselves). The CPU
    // evaluator and the GLSL emitter both run this.
    struct OpCall {
        const OpParams& params;
        std::array<int, 3> inputs;
        int table;
        bool sourceFunction = false;  // the op's function of its sources
    };
    // Whether the filtered program runs `op` at all (Operation::filteredRead).
    static bool runsFiltered(const Operation& op, bool matched) { return !matched || op.filteredRead; }
    static OpCall filteredCall(const Operation& op, bool matched) {
        if (matched && op.sourceFunction)
            return {op.sourceFunction->params, op.sourceFunction->inputs, op.sourceFunction->table, true};
        return {op.params, op.inputs, op.table};
    }
    // The node a table belongs to: its op's, or the op whose function of its sources it tabulates.
    const std::string& tableNode(int table) const;
    // Whether the unfiltered program (the ops' own tables) or the filtered
    // one (filteredCall's, `matched` or not) reads table `table`: a GPU
    // program binds only what it reads.
    bool readsTable(int table, bool filtered, bool matched) const;

    int leafCount() const { return int(leafIds_.size()); }
    const std::vector<std::string>& leafIds() const { return leafIds_; }
    // The leaves in fields of two channels, which the estimators read:
    // consecutive leaves with examples of one size share a field, a leaf
    // without a partner fills both channels.
    const std::vector<TiledField>& leafPairs() const { return pairs_; }
    // The transform of uv each pair of leaves is seen through (transform nodes).
    const UvTransform& pairTransform(int pair) const { return pairTransforms_[size_t(pair)]; }
    // Whether an operation reads the covariance of the pair's two leaves (a
    // lean node's slopes): its estimator then builds the covariance pyramid.
    bool pairCovariance(int pair) const { return pairCovariance_[size_t(pair)]; }
    // Where leaf k is: its field in leafPairs() and its channel there.
    std::array<int, 2> leafLocation(int k) const { return leafLocation_[size_t(k)]; }
    const TilingBlendingNoise& leaf(int k) const {
        return pairs_[size_t(leafLocation_[size_t(k)][0])].channel(leafLocation_[size_t(k)][1]);
    }
    // The first leaf's example side: uv = texels / this (View, Camera).
    int exampleSize() const { return leaf(0).example().size(); }
    const std::vector<Operation>& operations() const { return operations_; }
    const std::vector<Table>& tables() const { return tables_; }
    int outputSlot() const { return leafCount() + int(operations_.size()) - 1; }
    // The table of a program that is a plain pattern's H ∘ N: one colormap
    // op over the two channels of one pair of leaves, in order; else null.
    // The evaluators run such a program through one table lookup per pixel,
    // as the interpreter would (bit-identical; tested), at the plain
    // pattern's speed.
    const ColormapTable* plainColormap() const;
    // Whether an op lights its colour (a lean op): it reads the eye and the
    // light, so the renders pass each pixel's, and a scene draws its colour
    // as it is.
    bool shadesLight() const;
    const GridLayout& grid() const { return pairs_.front().grid(); }

    // S(uv): the leaves at uv (after T⁻¹ for Gaussianized exemplars) through the program.
    Rgb evaluate(double u, double v) const;
    // The program on given leaf values (one per leaf, in output space), seen from above.
    Rgb fromLeafValues(const std::vector<float>& values) const;
    // lastSlot: stop after this slot and return its value (−1: the output);
    // eye: the unit direction towards the eye, which a lean node reads
    // (evaluate(u, v) and the renders: from above).
    Rgb evaluate(double u, double v, int lastSlot, const Direction& eye) const;
    // Unfiltered, one sample per pixel centre, multi-threaded; the leaves in
    // SIMD lanes and the ops a row at a time, unless `kernel` asks for the
    // scalar reference.
    Image render(const View& view, const Progress& progress = {}, CpuKernel kernel = CpuKernel::Simd) const;
    // The value of any leaf or operation node over the same view (a field
    // as gray, clamped to [0, 1]; a colour as it is). InputError naming the
    // node if it is neither.
    Image renderNode(const View& view, const std::string& id) const;

private:
    friend class FilteredGraph;
    struct FieldRanges {
        std::vector<float> lo, hi;  // per slot, of a field's value (a colour's red)
    };
    // Each slot's range over the leaves' ranges: InputError naming the first
    // operation whose values can leave [−kMaxFieldValue, kMaxFieldValue];
    // a table's axis whose input is an op's field within [0, 1] becomes a
    // Beta axis (OpTable::beta).
    static FieldRanges settleProgramRanges(GraphPattern& p, const std::vector<NoiseExample>& examples,
                                           const std::string& context);
    // Filtered, an op whose inputs are functions of at most two slots, its
    // sources (leaves, or root ops: fields that read more sources, or ops
    // that read the eye, a pair's covariance or a colour root; two sources
    // read no leaf in common), is itself a function F of them. Moment
    // matching loses what is known of F where the op reads a source through
    // other ops (their fields are taken as Gaussian or Beta) or reads one
    // twice (two functions of one source are correlated, not independent
    // as the ops take their inputs). There, if F holds its values at the
    // table's ends where a source reaches beyond [0, 1] (as a table lookup
    // does), the op gets a table of F (Operation::sourceFunction), whose
    // prefiltered lookup averages F under its independent sources'
    // distributions as their moments give them (exact for leaves' Gaussians;
    // docs/MATH.md, "Functions of one or two sources"). Only ops whose
    // values the filtered program reads.
    static void planSourceFunctions(GraphPattern& p, const std::vector<NoiseExample>& examples,
                                    const FieldRanges& ranges);
    // Op slot q's function of `sources` (ascending), its table added; false
    // (nothing added) where F does not hold its ends beyond [0, 1], its
    // table would pass kMaxGraphTableEntries or the op evaluations so far
    // (`work`, which it adds to) kMaxFunctionWork.
    static bool planSourceFunction(GraphPattern& p, const std::vector<NoiseExample>& examples,
                                   const FieldRanges& ranges, int q, const std::vector<int>& sources, long long& work);
    // One pixel's slots: outputSlot() + 2 values, the last vec3(0) (what an
    // op reads for an input it lacks).
    using Slots = std::vector<kernel::vec3>;
    Slots makeSlots() const { return Slots(size_t(outputSlot() + 2), kernel::vec3(0.0f)); }
    // The operations on slots whose leaves are set; returns slot `lastSlot`.
    Rgb run(Slots& slots, int lastSlot, const Direction& eye) const;
    // The operations on rows of n pixels, each op chosen once per row: slot
    // k's values at rows + k·n, as many rows as a pixel has slots (the last
    // all vec3(0)); stops after slot lastSlot. run() is its one-pixel case.
    void runRows(kernel::vec3* rows, int n, int lastSlot, const Direction& eye) const;
    // evaluate(u, v, lastSlot, eye) in the caller's slots (no allocation per point).
    Rgb evaluate(double u, double v, int lastSlot, const Direction& eye, Slots& slots) const;
    Image renderPixels(const View& view, const Progress& progress, int lastSlot, bool gray, CpuKernel kernel) const;
    std::vector<std::string> leafIds_;
    std::vector<TiledField> pairs_;
    std::vector<UvTransform> pairTransforms_;
    std::vector<bool> pairCovariance_;
    bool untransformed_ = true;
    std::vector<std::array<int, 2>> leafLocation_;
    std::vector<Operation> operations_;
    std::vector<Table> tables_;
};

// How the moments of a non-linear node's output field are passed on.
enum class GraphMoments {
    Matched,   // mean and variance (moment matching through the (g, g²) tables)
    MeanOnly,  // the mean alone, variance 0: what filtering only the last transfer function amounts to
};
inline const EnumNames<GraphMoments> kGraphMomentsNames{{"matched", GraphMoments::Matched},
                                                        {"mean-only", GraphMoments::MeanOnly}};

// A program filtered through a camera (pattern/filter_options.h): source
// point / estimators / exact / reference, the prefiltered tables' mode,
// anisotropy, variance estimator, reference samples, 8-bit pyramids.
// The response is the program's last op (GraphPattern::build chose it).
class FilteredGraph final : public ViewRenderer {
public:
    using Direction = GraphPattern::Direction;
    // With `parts`, the estimators and prefiltered tables built before from
    // the same inputs are taken from it, and the new ones kept there.
    FilteredGraph(const GraphPattern& graph, const FilterOptions& options, GraphMoments moments = GraphMoments::Matched,
                  PartCache* parts = nullptr);

    // The colour of sky pixels: the program on the whole examples' moments
    // (for the point source, which prefilters no table, on their means when
    // an op reads a table); a plain pattern's program: its average colour
    // E[H(N)] in every mode.
    const Rgb& skyColour() const { return sky_; }
    // eye: the unit direction towards the eye (Camera::viewDirection), which a lean node reads.
    Rgb shade(bool onPlane, double u, double v, const Jacobian& j,
              const Direction& eye = GraphPattern::kFromAbove) const;
    Image render(const Camera& camera, const Progress& progress = {}) const override;
    int exampleSize() const override { return graph_.exampleSize(); }

    // The program on the leaves' moments (mean, variance per leaf) and the
    // covariance of each pair's two leaves (a lean node's slopes; none: 0).
    Rgb fromMoments(const std::vector<std::array<float, 2>>& leafMoments,
                    const std::vector<float>& pairCovariances = {},
                    const Direction& eye = GraphPattern::kFromAbove) const;
    // The estimators of leaf pair k (built for the estimators source only)
    // and the prefiltered table of GraphPattern table k, for the GPU.
    const FootprintEstimator& estimator(int pair) const { return *estimators_.at(size_t(pair)); }
    const std::shared_ptr<const FootprintEstimator>& sharedEstimator(int pair) const {
        return estimators_.at(size_t(pair));
    }
    size_t estimatorCount() const { return estimators_.size(); }
    // (Null, and table() a logic_error, for a table this program does not
    // read: GraphPattern::readsTable.)
    const PrefilteredColormap& table(int k) const {
        if (!tables_.at(size_t(k)))
            throw std::logic_error("FilteredGraph::table: the program does not read table " + std::to_string(k));
        return *tables_[size_t(k)];
    }
    const std::shared_ptr<const PrefilteredColormap>& sharedTable(int k) const { return tables_.at(size_t(k)); }

private:
    // What one thread reuses from pixel to pixel, so that shading a pixel allocates nothing.
    struct Scratch {
        std::vector<Footprint> footprints;  // one per estimator
        std::vector<FootprintStats> stats;  // one per leaf pair
        std::vector<float> covariances;     // one per leaf pair
        GraphPattern::Slots slots;          // the program's values
    };
    Rgb shade(bool onPlane, double u, double v, const Jacobian& j, const Direction& eye, Scratch& scratch) const;
    // The program on the moments in scratch.slots' leaves and scratch.covariances.
    Rgb runFiltered(Scratch& scratch, const Direction& eye) const;
    Rgb fromPairStats(Scratch& scratch, const Direction& eye) const;  // scratch.stats: one per leaf pair
    Rgb plainColour(const FootprintStats& s) const;  // a plain program's colour of its pair's statistics
    void footprints(double u, double v, const Jacobian& j, Scratch& scratch) const;  // one per estimator
    Rgb shade(Scratch& scratch, const Direction& eye) const;  // estimators, on scratch.footprints
    // A plain program's zoom through one-probe footprints (a zoom's are
    // isotropic) with the paper's or Deliot–Heitz's variances: each level's
    // texel statistics of a row in SIMD lanes, then per pixel the kernel's
    // loop over them (or a single texel's statistics, as estimate() takes
    // them) and the prefiltered table. zoomInLanes: whether `shape` (the
    // zoom's footprint) and the options allow it.
    bool zoomInLanes(const Footprint& shape) const;
    Image renderZoomInLanes(const Camera& camera, const Footprint& shape, const Progress& progress) const;
    // The reference through a zoom: the point image at n times the
    // resolution, box-filtered (its pixels tile the plane).
    Image renderZoomReference(const Camera& camera, const Progress& progress) const;
    const GraphPattern& graph_;
    FilterOptions options_;
    GraphMoments moments_;
    // Shared with a PartCache and the other renderers built from it.
    std::vector<std::shared_ptr<const FootprintEstimator>> estimators_;  // one per leaf pair
    std::vector<std::shared_ptr<const PrefilteredColormap>> tables_;     // per GraphPattern table
    Rgb sky_{};
    bool plain_ = false;  // the program is a plain pattern's (GraphPattern::plainColormap)
    // Whether the ops' functions of their sources stand in for them
    // (GraphPattern::filteredCall): moment matching with prefiltered tables.
    bool readsFunctions_ = false;
};

}  // namespace stochtex
