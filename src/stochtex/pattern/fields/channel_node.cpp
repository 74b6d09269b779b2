#include "stochtex/pattern/fields/fields.h"

#include "stochtex/pattern/fields/field_node.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

NodeInfo channelNode() {
    NodeInfo n{"channel",
               "linear",
               "One channel of a tiled field, on the tiles every channel of that field shares",
               {{"field", PortType::Channels, "The tiled field"}},
               PortType::Field,
               {{"index", ParamType::Integer, "The channel, from 0 (red, green, blue, alpha of a colour image)", 0, 0,
                 3}}};
    // The tiled field's image, this channel of it (GraphPattern gives every
    // channel of one tiled field the same tiles).
    n.fold = [](const FieldFold& f) {
        NoiseSpec ns = f.inputNode("field").noise;
        ns.channel = int(f.number("index"));
        return buildNoiseExample(ns, f.where + " (channel)");
    };
    return n;
}

}  // namespace stochtex
