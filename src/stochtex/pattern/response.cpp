#include "stochtex/pattern/response.h"

#include <stdexcept>

#include "stochtex/core/error.h"
#include "stochtex/kernel/lean.h"
#include "stochtex/pattern/pattern_parts.h"

namespace stochtex {

LeanResponse::LeanResponse(const LeanShading& shading, bool covariance)
    : shading_(validatedShading(shading)), covariance_(covariance) {}

Rgb LeanResponse::filtered(const FootprintStats& s, const Direction& camera) const {
    using namespace kernel;
    const auto v3 = [](const std::array<double, 3>& d) { return vec3(float(d[0]), float(d[1]), float(d[2])); };
    const LeanLobe lobe = leanLobe(vec2(s.mean[0], s.mean[1]), vec2(s.varX, s.varY), covariance_ ? s.cov : 0.0f,
                                   float(shading_.roughness));
    const vec3 view = shading_.view ? v3(*shading_.view) : vec3(camera[0], camera[1], camera[2]);
    const vec3 c = leanShade(lobe, v3(shading_.light), view,
                             vec3(shading_.albedo[0], shading_.albedo[1], shading_.albedo[2]), float(shading_.specular));
    return {c.x, c.y, c.z};
}

Rgb LeanResponse::point(float slopeX, float slopeY, const Direction& camera) const {
    FootprintStats s;
    s.mean = {slopeX, slopeY};
    return filtered(s, camera);
}

std::unique_ptr<Response> makeResponse(const ResponseOptions& options, const ColormapTable& h,
                                       const LeanShading* shading) {
    switch (options.kind) {
        case ResponseKind::PrefilteredColormap:
            return std::make_unique<PrefilteredColormapResponse>(h, options.prefilter);
        case ResponseKind::Lean:
            if (!shading) throw InputError::parameter("response", "lean shades a normal map; the pattern has none");
            return std::make_unique<LeanResponse>(*shading, options.covariance);
    }
    throw std::invalid_argument("makeResponse: unknown response kind " + std::to_string(int(options.kind)));
}

}  // namespace stochtex
