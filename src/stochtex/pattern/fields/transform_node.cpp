#include "stochtex/pattern/fields/fields.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/pattern/fields/field_node.h"

namespace stochtex {

namespace {

// A chain of transform nodes may do in all what one node may: scale uv by
// [1/64, 64] and offset it by at most 1e4 example periods along each axis.
// Beyond that the composed map leaves what the renderers resolve: at 1e4
// periods a float uv (the GPU's) is good to half a texel of a 512² example,
// and 172 nodes at scale 64 overflow float altogether (inf in the generated
// GLSL, an out-of-range cast in the CPU's texel lookup).
constexpr double kMaxComposedScale = 64;
constexpr double kMaxComposedOffset = 1e4;

void checkComposed(const FieldSight& s, const UvTransform& r) {
    const std::string pointer = "/nodes/" + s.node.id + "/";
    const double det = r.m[0] * r.m[3] - r.m[1] * r.m[2];
    const double scale = std::sqrt(std::abs(det));  // a similarity: scale² = |det|
    if (!(scale <= kMaxComposedScale && scale >= 1 / kMaxComposedScale))
        throw InputError(s.where + ": " + pointer + "scale: composed with the transforms it reads, uv is scaled by " +
                         formatValue(scale) + "; a chain of transform nodes may scale it by [1/64, 64] in all");
    for (int i = 0; i < 2; ++i)
        if (!(std::abs(r.t[size_t(i)]) <= kMaxComposedOffset))
            throw InputError(s.where + ": " + pointer + (i == 0 ? "offset_u" : "offset_v") +
                             ": composed with the transforms it reads, uv is offset by " + formatValue(r.t[size_t(i)]) +
                             " example periods; a chain of transform nodes may offset it by at most 1e4 in all");
}

}  // namespace

NodeInfo transformNode() {
    NodeInfo n{"transform",
               "linear",
               "The field seen through a transform of uv: input(scale · R(angle) · uv + offset), tiles and all",
               {{"input", PortType::Field, "The field"}},
               PortType::Field,
               {{"angle", ParamType::Number, "Rotation, degrees from +u towards +v", 0, -360, 360},
                {"scale", ParamType::Number, "Scale of uv (2: features half as large)", 1, 1.0 / 64, 64},
                {"offset_u", ParamType::Number, "Offset along u, example periods", 0, -1e4, 1e4},
                {"offset_v", ParamType::Number, "Offset along v, example periods", 0, -1e4, 1e4}}};
    // The same example, seen through another uv.
    n.fold = [](const FieldFold& f) { return f.input("input"); };
    n.seenThrough = [](const FieldSight& s) {
        // input(M_in · (A·uv + b) + t_in): A = scale·R(angle), b = offset.
        const UvTransform in = s.input("input");
        const double a = s.number("angle") * std::numbers::pi / 180, k = s.number("scale");
        const double c = k * std::cos(a), sn = k * std::sin(a);
        const std::array<double, 4> m{c, -sn, sn, c};
        const std::array<double, 2> b{s.number("offset_u"), s.number("offset_v")};
        UvTransform r;
        r.m = {in.m[0] * m[0] + in.m[1] * m[2], in.m[0] * m[1] + in.m[1] * m[3], in.m[2] * m[0] + in.m[3] * m[2],
               in.m[2] * m[1] + in.m[3] * m[3]};
        const std::array<double, 2> mb = in.linear(b[0], b[1]);
        r.t = {mb[0] + in.t[0], mb[1] + in.t[1]};
        checkComposed(s, r);
        return r;
    };
    return n;
}

}  // namespace stochtex
