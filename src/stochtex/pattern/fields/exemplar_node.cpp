#include "stochtex/pattern/fields/fields.h"

#include "stochtex/pattern/fields/field_node.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

NodeInfo exemplarNode() {
    NodeInfo n{"exemplar",
               "source",
               "An image as the example (periodic), tiled and blended",
               {},
               PortType::Field,
               {{"path", ParamType::Path, "The image (1 channel or colour, taken as gray), relative to the graph file",
                 nlohmann::json()},
                {"gaussianize", ParamType::Boolean,
                 "Blend the histogram-transformed exemplar and map back (paper §5); such a field feeds a transfer "
                 "function directly, not a linear node",
                 true}}};
    n.parsed = [](GraphNode& g, const JsonReader&) {
        g.noise.source = NoiseSpec::Source::Image;
        g.noise.gaussianize = g.numbers["gaussianize"] != 0;
    };
    n.fold = [](const FieldFold& f) { return buildNoiseExample(f.node.noise, f.where); };
    return n;
}

}  // namespace stochtex
