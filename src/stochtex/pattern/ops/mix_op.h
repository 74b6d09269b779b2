#pragma once
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/mix_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct MixOp {
    using Params = kernel::MixParams;
    static constexpr const char* kKernel = "mix_op";
    static NodeInfo info() {
        return {"mix",
                "colour",
                "a + t·(b − a): two colours mixed by a field (t not clamped)",
                {{"a", PortType::Colour, "The colour where t = 0"},
                 {"b", PortType::Colour, "The colour where t = 1"},
                 {"t", PortType::Field, "The mixing field"}},
                PortType::Colour,
                {}};
    }
    static Params bind(OpBuild&) { return {0.0f}; }
};

}  // namespace stochtex
