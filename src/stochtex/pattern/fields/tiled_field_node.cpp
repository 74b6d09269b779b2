#include "stochtex/pattern/fields/fields.h"

#include <stdexcept>

#include "stochtex/pattern/fields/field_node.h"

namespace stochtex {

// Not a field itself: its channel nodes are, on the tiles they share
// (graphTileGroup). It is linear (it has a fold, so its channels are), but
// nothing folds it: a tiled field is never a field input, and its fold
// throws.
NodeInfo tiledFieldNode() {
    NodeInfo n{"tiled_field",
               "source",
               "An image of K channels (1 to 4) as K examples tiled and blended with the same tiles and weights: a "
               "noise vector field (paper eq. 7) whose channels keep their correlations; channel nodes read them",
               {},
               PortType::Channels,
               {{"path", ParamType::Path, "The image (1 to 4 channels), relative to the graph file", nlohmann::json()},
                {"transfer", ParamType::Choice,
                 "How its codes become values: auto (srgb, but linear for a float file such as EXR), srgb (colour "
                 "channels decoded to linear light; alpha stays data) or linear (as data)",
                 "auto", 0, 0, nullptr, {"auto", "srgb", "linear"}},
                {"gaussianize", ParamType::Boolean,
                 "Blend each channel's histogram-transformed example and map back (paper §5); such a channel feeds "
                 "a transfer function directly, not a linear node",
                 true}}};
    n.parsed = [](GraphNode& g, const JsonReader&) {
        g.noise.source = NoiseSpec::Source::Image;
        g.noise.gaussianize = g.numbers["gaussianize"] != 0;
        if (g.numbers["transfer"] != 0)  // 0: auto
            g.noise.transfer = g.numbers["transfer"] == 1 ? Transfer::Srgb : Transfer::Linear;
    };
    n.fold = [](const FieldFold& f) -> NoiseExample {
        throw std::logic_error("tiled_field node " + f.node.id + ": its channels are fields, it is not");
    };
    return n;
}

}  // namespace stochtex
