#pragma once
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/square_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct SquareOp {
    using Params = kernel::SquareParams;
    static constexpr const char* kKernel = "square_op";
    static NodeInfo info() {
        return {"square",
                "transfer",
                "scale · input²: a field's energy (filtered exactly for a Gaussian input)",
                {{"input", PortType::Field, "The field"}},
                PortType::Field,
                {{"scale", ParamType::Number, "Factor", 1, -100, 100}}};
    }
    static Params bind(OpBuild& b) { return {b.number("scale")}; }
};

}  // namespace stochtex
