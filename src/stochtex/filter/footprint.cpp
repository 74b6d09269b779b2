#include "stochtex/filter/footprint.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "stochtex/core/error.h"

namespace stochtex {

Footprint makeFootprint(double u, double v, const Jacobian& j, int exampleSize, int maxLod, int maxAniso) {
    if (maxAniso < 1 || maxAniso > kMaxAnisotropy)
        throw InputError("anisotropy K must be in [1, 16] (got " + std::to_string(maxAniso) + ")");
    if (!std::isfinite(u) || !std::isfinite(v) || !std::isfinite(j.dudx) || !std::isfinite(j.dvdx) ||
        !std::isfinite(j.dudy) || !std::isfinite(j.dvdy))
        throw InputError("footprint: non-finite position or Jacobian");
    const double w = exampleSize;
    // sqrt rather than hypot: no overflow is possible here and hypot is a
    // slow libm call on the per-pixel path.
    const double px = w * std::sqrt(j.dudx * j.dudx + j.dvdx * j.dvdx);
    const double py = w * std::sqrt(j.dudy * j.dudy + j.dvdy * j.dvdy);
    const bool xMajor = px >= py;
    const double pmax = std::max(px, py), pmin = std::min(px, py);
    int n = 1;
    if (maxAniso > 1 && pmin > 0) n = int(std::min<double>(std::ceil(pmax / pmin - 1e-9), maxAniso));
    else if (maxAniso > 1 && pmax > 0) n = maxAniso;  // degenerate (a line): as anisotropic as allowed
    n = std::max(n, 1);
    const double rho = pmax / n;
    const float lod = rho > 0 ? float(std::clamp(std::log2(rho), 0.0, double(maxLod))) : 0.0f;
    Footprint f;
    f.count = n;
    const double au = xMajor ? j.dudx : j.dudy, av = xMajor ? j.dvdx : j.dvdy;
    for (int k = 0; k < n; ++k) {
        const double t = n == 1 ? 0.0 : (k + 0.5) / n - 0.5;
        f.probes[size_t(k)] = Probe{u + t * au, v + t * av, lod, 1.0f / float(n)};
    }
    return f;
}

}  // namespace stochtex
