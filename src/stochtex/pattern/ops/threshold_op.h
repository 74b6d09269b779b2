#pragma once
#include <nlohmann/json.hpp>

#include "stochtex/pattern/ops/curve_op.h"
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/threshold_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct ThresholdOp {
    using Params = kernel::ThresholdParams;
    static constexpr const char* kKernel = "threshold_op";
    static NodeInfo info() {
        return {"threshold",
                "transfer",
                "A soft threshold: 0 below edge − width/2, 1 above edge + width/2, the smoothstep between",
                {{"input", PortType::Field, "The field"}},
                PortType::Field,
                {{"edge", ParamType::Number, "The value thresholded at (s = ½ there)", 0.5, -10, 10, nullptr, {}, 1},
                 {"width", ParamType::Number, "Width of the soft step, in the field's values", 0.05, 1e-3, 10, nullptr, {}, 1},
                 {"resolution", ParamType::Integer, "Entries of the table the filtered value reads", 256, 2, 1024}}};
    }
    // The table of s that the filtered value reads (CurveOp::momentTable).
    static Params bind(OpBuild& b) {
        const Params p{b.number("edge"), b.number("width")};
        b.addTable(CurveOp::momentTable(int(b.node.numbers.at("resolution")), b.gaussianizedInput("input"),
                                        [&](float x) { return kernel::thresholdValue(p, x); }));
        return p;
    }
};

}  // namespace stochtex
