#pragma once
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/compose_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct ComposeOp {
    using Params = kernel::ComposeParams;
    static constexpr const char* kKernel = "compose_op";
    static NodeInfo info() {
        return {"compose",
                "colour",
                "A colour from three fields, (r, g, b) in linear light: with the channels of a tiled field, a colour "
                "exemplar tiled and blended",
                {{"r", PortType::Field, "Red"}, {"g", PortType::Field, "Green"}, {"b", PortType::Field, "Blue"}},
                PortType::Colour,
                {}};
    }
    static Params bind(OpBuild&) { return {0.0f}; }
};

}  // namespace stochtex
