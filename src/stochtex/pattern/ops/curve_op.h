#pragma once
#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/noise/example.h"
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/curve_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct CurveOp {
    using Params = kernel::CurveParams;
    static constexpr const char* kKernel = "curve_op";
    static NodeInfo info() {
        return {"curve",
                "transfer",
                "A 1D transfer function: the piecewise-linear curve through the points",
                {{"input", PortType::Field, "The field (read in [0, 1], clamped)"}},
                PortType::Field,
                {{"points", ParamType::Curve, "[[x, y], ...]: x strictly increasing in [0, 1], y in [-100, 100]",
                  nlohmann::json(), 0, 0, nlohmann::json::parse("[[0, 0], [0.5, 1], [1, 0]]")},
                 {"resolution", ParamType::Integer, "Entries of the table the curve is sampled into", 256, 2, 1024}}};
    }
    // The piecewise-linear curve through the points at x (clamped to the ends).
    static double at(const std::vector<std::array<double, 2>>& points, double x) {
        if (x <= points.front()[0]) return points.front()[1];
        for (size_t k = 1; k < points.size(); ++k)
            if (x <= points[k][0]) {
                const auto &a = points[k - 1], &b = points[k];
                return a[1] + (x - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
            }
        return points.back()[1];
    }
    // A 1D function f of a field as the table curveMoments reads: R entries
    // of (f, f², 0) over [0, 1] on two rows; in blending space, with a
    // Gaussianized input, f∘T⁻¹.
    template <class F>
    static OpTable momentTable(int resolution, const NoiseExample* gaussianized, F&& f) {
        const auto table = [&](const NoiseExample* input) {
            return tabulate(resolution, 2, [&](int i, int) {
                float x = float(i) / float(resolution - 1);
                if (input) x = input->toOutput(x);
                return kernel::momentEntry(float(f(x)));
            });
        };
        return {table(nullptr), table(gaussianized), true};
    }
    static Params bind(OpBuild& b) {
        b.addTable(momentTable(int(b.node.numbers.at("resolution")), b.gaussianizedInput("input"),
                               [&](float x) { return at(b.node.curve, x); }));
        return {0.0f};
    }
};

}  // namespace stochtex
