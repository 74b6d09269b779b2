#pragma once
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/pattern/fields/field_node.h"
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/sum_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct SumOp {
    using Params = kernel::SumParams;
    static constexpr const char* kKernel = "sum_op";
    static NodeInfo info() {
        NodeInfo n{"sum",
                "linear",
                "weight_a · a + weight_b · b, two fields with examples of one size",
                {{"a", PortType::Field, "First field"}, {"b", PortType::Field, "Second field"}},
                PortType::Field,
                {{"weight_a", ParamType::Number, "Weight of a", 0.5, -100, 100},
                 {"weight_b", ParamType::Number, "Weight of b", 0.5, -100, 100}}};
        // Over fields that fold, linear: the weighted sum of their examples.
        n.fold = [](const FieldFold& f) {
            const NoiseExample a = f.linearInput("a"), b = f.linearInput("b");
            if (a.size() != b.size())
                throw InputError(f.where + " (sum): its inputs' examples are " + std::to_string(a.size()) + " and " +
                                 std::to_string(b.size()) + " texels wide; a sum needs one size");
            Image v = a.values();
            const float wa = float(f.number("weight_a")), wb = float(f.number("weight_b"));
            for (size_t i = 0; i < v.data().size(); ++i) v.data()[i] = wa * v.data()[i] + wb * b.values().data()[i];
            return NoiseExample(std::move(v));
        };
        n.seenThrough = [](const FieldSight& s) {
            const UvTransform r = s.input("a");
            if (!(s.input("b") == r))
                throw InputError(s.where + ": its inputs are seen through different transforms of uv; a sum needs one");
            return r;
        };
        return n;
    }
    static Params bind(OpBuild& b) { return {b.number("weight_a"), b.number("weight_b")}; }
};

}  // namespace stochtex
