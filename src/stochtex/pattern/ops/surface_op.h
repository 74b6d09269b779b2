#pragma once
#include "stochtex/kernel/lean.h"
#include "stochtex/pattern/ops/op_host.h"

STOCHTEX_OP_KERNEL_BEGIN
#include "stochtex/pattern/ops/surface_op.glsl"
STOCHTEX_OP_KERNEL_END

namespace stochtex {

// The maps of a PBR material from a height field (bake-image --pbr, the
// normal, roughness and height responses of a pattern's normal map): as a
// lean node, the graph builds its height's slopes (first port) on the
// height's tiles; its second port reads the height itself.
struct SurfaceOp {
    using Params = kernel::SurfaceParams;
    static constexpr const char* kKernel = "surface_op";
    static NodeInfo info() {
        return {"surface",
                "shading",
                "A PBR material's map of a height field: its tangent-space normal (OpenGL convention, of the "
                "footprint's mean slope), its roughness (GGX r of the slope lobe's spread: the base roughness and "
                "the footprint's slope variances) or its height (the footprint's mean)",
                {{"height", PortType::Field, "The height field, read through its slopes (normal, roughness)"},
                 {"value", PortType::Field, "The height field, read as it is (the height map)"}},
                PortType::Colour,
                {{"map", ParamType::Integer, "0: normal, 1: roughness, 2: height", 0, 0, 2},
                 {"amplitude", ParamType::Number, "RMS slope per axis the height field is scaled to", 0.3, 1e-3, 10},
                 {"roughness", ParamType::Number, "Base Beckmann roughness m of each micro-facet", 0.1, 1e-3, 2},
                 {"covariance", ParamType::Boolean, "Build the slopes' covariance (no map reads it)", false}},
                -1,
                "height"};
    }
    static Params bind(OpBuild& b) { return {b.number("map"), b.number("roughness")}; }
};

}  // namespace stochtex
