#pragma once
#include <nlohmann/json.hpp>

#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/colour_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

// A constant colour. A graph still needs a field to be a texture: one whose
// output reads none is refused (GraphPattern::build).
struct ColourOp {
    using Params = kernel::ColourParams;
    static constexpr const char* kKernel = "colour_op";
    static NodeInfo info() {
        return {"colour",
                "colour",
                "A constant colour (an albedo for lean, an end of a mix)",
                {},
                PortType::Colour,
                {{"colour", ParamType::Colour,
                  "\"#rrggbb\" or [r, g, b] in [0, 1]: sRGB components, decoded to linear light as every colour of a "
                  "pattern file",
                  "#767676"}}};
    }
    static Params bind(OpBuild& b) { return {b.node.colour[0], b.node.colour[1], b.node.colour[2]}; }
};

}  // namespace stochtex
