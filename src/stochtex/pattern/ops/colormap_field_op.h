#pragma once
#include <nlohmann/json.hpp>

#include "stochtex/pattern/ops/op_host.h"
#include "stochtex/pattern/pattern_parts.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/colormap_field_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

struct ColormapFieldOp {
    using Params = kernel::ColormapFieldParams;
    static constexpr const char* kKernel = "colormap_field_op";
    // Its point value is its table at (x, y), a row of them a row of lookups
    // (ops.h, opPointRow); filtered it matches moments, so not a plain lookup.
    static constexpr bool kPointLookup = true;
    static NodeInfo info() {
        return {"colormap_field",
                "transfer",
                "A 2D transfer function read as a field: one channel, or the luminance, of H(x, y) (paper Fig. 14)",
                {{"x", PortType::Field, "The colormap's horizontal coordinate"},
                 {"y", PortType::Field, "The colormap's vertical coordinate"}},
                PortType::Field,
                {{"colormap", ParamType::Colormap,
                  "A COLORMAP (docs/PATTERNS.md); \"transfer\": \"linear\" reads its colours as data", nlohmann::json(),
                  0, 0, nlohmann::json::parse(R"({"type": "phasor", "profile": "sine"})")},
                 {"channel",
                  ParamType::Choice,
                  "The channel of H read: red, green, blue, or luminance (Rec. 709, linear)",
                  "luminance",
                  0,
                  0,
                  nullptr,
                  {"red", "green", "blue", "luminance"}}}};
    }
    // The table (g, g², 0) of H's channel, and of H with the Gaussianized inputs' T⁻¹ folded in.
    static Params bind(OpBuild& b) {
        const ColormapTable h = b.colormap(b.node.colormap);
        const ColormapTable blended = foldInverseTransforms(h, b.gaussianizedInput("x"), b.gaussianizedInput("y"));
        const int channel = int(b.node.numbers.at("channel"));
        const auto field = [channel](const ColormapTable& t) {
            return tabulate(t.resolutionX(), t.resolutionY(), [&](int i, int j) {
                const Rgb e = t.entry(i, j);
                return kernel::momentEntry(kernel::graphChannel(kernel::vec3(e[0], e[1], e[2]), channel));
            });
        };
        b.addTable({field(h), field(blended), true});
        return {0.0f};
    }
};

}  // namespace stochtex
