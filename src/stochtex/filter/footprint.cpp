#include "stochtex/filter/footprint.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "stochtex/core/error.h"
#include "stochtex/kernel/footprint.h"

namespace stochtex {

Footprint makeFootprint(double u, double v, const Jacobian& j, int exampleSize, int maxLod, int maxAniso) {
    if (maxAniso < 1 || maxAniso > kMaxAnisotropy)
        throw InputError::parameter("maxAniso", "(K) must be in [1, 16], got " + std::to_string(maxAniso));
    if (!std::isfinite(u) || !std::isfinite(v) || !std::isfinite(j.dudx) || !std::isfinite(j.dvdx) ||
        !std::isfinite(j.dudy) || !std::isfinite(j.dvdy))
        throw InputError("footprint: non-finite position or Jacobian");
    // The probe layout is the kernel's (kernel/footprint.glsl), as in the
    // shaders; the centre stays in double (uv may be far from the origin).
    const kernel::ProbeLayout layout =
        kernel::probeLayout(kernel::vec2(float(j.dudx), float(j.dvdx)), kernel::vec2(float(j.dudy), float(j.dvdy)),
                            float(exampleSize), maxAniso, maxLod);
    return Footprint{u, v, layout};
}

}  // namespace stochtex
