#pragma once
#include <cmath>
#include <numbers>

#include "stochtex/kernel/lean.h"
#include "stochtex/pattern/ops/op_host.h"
#include "stochtex/pattern/pattern_parts.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/lean_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

// The graph builds a lean node's inputs: its height's slopes (scaled to
// `amplitude`) as two leaves on the height's tiles, then the albedo
// (GraphPattern::build).
struct LeanOp {
    using Params = kernel::LeanParams;
    static constexpr const char* kKernel = "lean_op";
    static NodeInfo info() {
        return {
            "lean",
            NodeKind::Op,
            "shading",
            "LEAN mapping (paper §6.5): the height field's slopes as micro-facet normals; their footprint mean and "
            "covariance make an anisotropic Beckmann lobe, lit by a directional light",
            {{"height", PortType::Field,
              "The height field (linear in the sources: its slopes are exact on its example)"},
             {"albedo", PortType::Colour, "The diffuse colour (linear light)"}},
            PortType::Colour,
            {{"amplitude", ParamType::Number, "RMS slope per axis the height field is scaled to", 0.3, 1e-3, 10},
             {"roughness", ParamType::Number, "Base Beckmann roughness m of each micro-facet", 0.1, 1e-3, 2},
             {"specular", ParamType::Number, "Weight of the lobe's reflection", 0.05, 0, 100},
             {"light_azimuth", ParamType::Number,
              "Direction towards the light, degrees from +u towards +v (a scene's own light replaces it)", -90, -360,
              360},
             {"light_elevation", ParamType::Number, "Elevation of the light above the plane, degrees", 53.13, 1, 90},
             {"covariance", ParamType::Boolean, "Read the slopes' covariance (false: the variant without it, ĉov := 0)",
              true}}};
    }
    static Params bind(OpBuild& b) {
        LeanShading shading;
        const double azimuth = b.node.numbers.at("light_azimuth") * std::numbers::pi / 180;
        const double elevation = b.node.numbers.at("light_elevation") * std::numbers::pi / 180;
        shading.light = {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                         std::sin(elevation)};
        shading.roughness = b.node.numbers.at("roughness");
        shading.specular = b.node.numbers.at("specular");
        shading = validatedShading(shading);
        return {float(shading.roughness), float(shading.specular), float(shading.light[0]),
                float(shading.light[1]),  float(shading.light[2]), b.number("covariance")};
    }
};

}  // namespace stochtex
