#include "stochtex/pattern/cpu_renderer.h"

#include "stochtex/pattern/graph_pattern.h"

namespace stochtex {

namespace {

// An evaluator and its filtered view, which holds a reference to it: built
// in place, in that order, and never moved.
template <class Evaluator, class Filtered>
class Owning final : public ViewRenderer {
public:
    Owning(Evaluator evaluator, const FilterOptions& options, PartCache* parts)
        : evaluator_(std::move(evaluator)), filtered_(evaluator_, options, GraphMoments::Matched, parts) {}
    Image render(const Camera& camera, const Progress& progress) const override {
        return filtered_.render(camera, progress);
    }
    int exampleSize() const override { return filtered_.exampleSize(); }

private:
    Evaluator evaluator_;
    Filtered filtered_;
};

}  // namespace

std::unique_ptr<ViewRenderer> makeCpuRenderer(const PatternSpec& spec, const FilterOptions& options, PartCache* parts) {
    return std::make_unique<Owning<GraphPattern, FilteredGraph>>(GraphPattern::build(spec, options.response, parts),
                                                                 options, parts);
}

}  // namespace stochtex
