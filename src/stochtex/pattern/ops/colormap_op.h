#pragma once
#include <nlohmann/json.hpp>

#include "stochtex/pattern/ops/op_host.h"
#include "stochtex/pattern/pattern_parts.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/colormap_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct ColormapOp {
    using Params = kernel::ColormapParams;
    static constexpr const char* kKernel = "colormap_op";
    static constexpr bool kPlainLookup = true;  // its table at (x, y): over one pair, H ∘ N (ops.h, opIsPlainLookup)
    static NodeInfo info() {
        return {"colormap",
                "transfer",
                "The 2D transfer function H: colour = H(x, y) (paper eq. 1)",
                {{"x", PortType::Field, "N_x, the colormap's horizontal coordinate"},
                 {"y", PortType::Field, "N_y, the colormap's vertical coordinate"}},
                PortType::Colour,
                {{"colormap", ParamType::Colormap, "A COLORMAP: analytic, phasor, image or painted (docs/PATTERNS.md)",
                  nlohmann::json(), 0, 0, nlohmann::json::parse(R"({"type": "gaussian"})")}}};
    }
    // H, and H with the Gaussianized inputs' T⁻¹ folded in (what the prefiltered table is built from).
    static Params bind(OpBuild& b) {
        const ColormapTable h = b.colormap(b.node.colormap);
        b.addTable({h, foldInverseTransforms(h, b.gaussianizedInput("x"), b.gaussianizedInput("y")), false});
        return {0.0f};
    }
};

}  // namespace stochtex
