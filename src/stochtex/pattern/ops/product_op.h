#pragma once
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/product_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct ProductOp {
    using Params = kernel::ProductParams;
    static constexpr const char* kKernel = "product_op";
    static NodeInfo info() {
        return {"product",
                "transfer",
                "scale · a · b: one field modulating another (filtered exactly for independent fields)",
                {{"a", PortType::Field, "First field"}, {"b", PortType::Field, "Second field"}},
                PortType::Field,
                {{"scale", ParamType::Number, "Factor", 1, -100, 100}}};
    }
    static Params bind(OpBuild& b) { return {b.number("scale")}; }
};

}  // namespace stochtex
