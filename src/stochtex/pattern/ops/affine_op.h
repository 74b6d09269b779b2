#pragma once
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/affine_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct AffineOp {
    using Params = kernel::AffineParams;
    static constexpr const char* kKernel = "affine_op";
    static NodeInfo info() {
        return {"affine",
                NodeKind::Affine,
                "linear",
                "scale · field + offset",
                {{"input", PortType::Field, "The field"}},
                PortType::Field,
                {{"scale", ParamType::Number, "Factor", 1, -100, 100},
                 {"offset", ParamType::Number, "Added", 0, -100, 100}}};
    }
    static Params bind(OpBuild& b) { return {b.number("scale"), b.number("offset")}; }
};

}  // namespace stochtex
