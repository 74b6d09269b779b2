#pragma once
#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

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
    static constexpr bool kShadesLight = true;  // reads OpContext's eye and light (ops.h, opShadesLight)
    static NodeInfo info() {
        return {
            "lean",
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
             {"view_azimuth", ParamType::Number, "A fixed direction towards the viewer, degrees from +u towards +v",
              -90, -360, 360},
             {"view_elevation", ParamType::Number,
              "Its elevation above the plane, degrees; 0: no fixed view, the camera's eye (a lobe seen from where "
              "each pixel is seen)",
              0, 0, 90},
             {"covariance", ParamType::Boolean, "Read the slopes' covariance (false: the variant without it, ĉov := 0)",
              true}},
            -1,
            "height"};
    }
    // A unit direction from degrees (azimuth from +u towards +v, elevation above the plane).
    static std::array<double, 3> direction(double azimuthDegrees, double elevationDegrees) {
        const double azimuth = azimuthDegrees * std::numbers::pi / 180;
        const double elevation = elevationDegrees * std::numbers::pi / 180;
        std::array<double, 3> d{std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                std::sin(elevation)};
        for (double& c : d)
            if (std::abs(c) < 1e-12) c = 0;  // cos(90°) is 6e-17 in double: rounding, not a direction
        return d;
    }
    // The shading an engine lights the program with (export's manifest.json, `graph.lean`).
    static nlohmann::json manifest(const Params& l) {
        const auto n = shortestDecimal;
        return {{"roughness", n(l.roughness)},
                {"specular", n(l.specular)},
                {"light", {n(l.lightX), n(l.lightY), n(l.lightZ)}},
                {"view", l.viewZ != 0 ? nlohmann::json{n(l.viewX), n(l.viewY), n(l.viewZ)} : nlohmann::json()},
                {"covariance", l.covariance != 0}};
    }
    static Params bind(OpBuild& b) {
        LeanShading shading;
        shading.light = direction(b.node.numbers.at("light_azimuth"), b.node.numbers.at("light_elevation"));
        if (b.node.numbers.at("view_elevation") != 0)
            shading.view = direction(b.node.numbers.at("view_azimuth"), b.node.numbers.at("view_elevation"));
        shading.roughness = b.node.numbers.at("roughness");
        shading.specular = b.node.numbers.at("specular");
        shading = validatedShading(shading);
        const std::array<double, 3> view = shading.view.value_or(std::array<double, 3>{0, 0, 0});
        return {float(shading.roughness),
                float(shading.specular),
                float(shading.light[0]),
                float(shading.light[1]),
                float(shading.light[2]),
                b.number("covariance"),
                float(view[0]),
                float(view[1]),
                float(view[2])};
    }
};

}  // namespace stochtex
