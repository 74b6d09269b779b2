#pragma once
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/sum_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct SumOp {
    using Params = kernel::SumParams;
    static constexpr const char* kKernel = "sum_op";
    static NodeInfo info() {
        return {"sum",
                NodeKind::Sum,
                "linear",
                "weight_a · a + weight_b · b, two fields with examples of one size",
                {{"a", PortType::Field, "First field"}, {"b", PortType::Field, "Second field"}},
                PortType::Field,
                {{"weight_a", ParamType::Number, "Weight of a", 0.5, -100, 100},
                 {"weight_b", ParamType::Number, "Weight of b", 0.5, -100, 100}}};
    }
    static Params bind(OpBuild& b) { return {b.number("weight_a"), b.number("weight_b")}; }
};

}  // namespace stochtex
