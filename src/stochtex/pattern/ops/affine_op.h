#pragma once
#include "stochtex/pattern/fields/field_node.h"
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/affine_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct AffineOp {
    using Params = kernel::AffineParams;
    static constexpr const char* kKernel = "affine_op";
    static NodeInfo info() {
        NodeInfo n{"affine",
                "linear",
                "scale · field + offset",
                {{"input", PortType::Field, "The field"}},
                PortType::Field,
                {{"scale", ParamType::Number, "Factor", 1, -100, 100},
                 {"offset", ParamType::Number, "Added", 0, -100, 100}}};
        // Over a field that folds, linear: the affine map of its example, seen as it is.
        n.fold = [](const FieldFold& f) {
            Image v = f.linearInput("input").values();
            const float scale = float(f.number("scale")), offset = float(f.number("offset"));
            for (float& x : v.data()) x = scale * x + offset;
            return NoiseExample(std::move(v));
        };
        n.seenThrough = inputSight;
        return n;
    }
    static Params bind(OpBuild& b) { return {b.number("scale"), b.number("offset")}; }
};

}  // namespace stochtex
