#include "stochtex/pattern/camera.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"

namespace stochtex {

// The plane camera. A pixel position p (pixel centres at +½) gives the view
// ray's normalised image coordinates
//     n_x = (p_x − w/2)·T/h₂,  n_y = −(p_y − h₂)·T/h₂   (h₂ = h/2, T = tan(fov/2)),
// and with forward (0, −sin t, −cos t), up (0, −cos t, sin t), right (1, 0, 0)
// the ray direction d = (n_x, −s − n_y c, −c + n_y s), s = sin t, c = cos t.
// It meets the ground, a height H = scale·h₂/T below the eye (so that at
// t = 0 a pixel covers `scale` texels), at k = H/q with q = −d_z = c − n_y s:
//     texel = offset + (w, h)·scale/2 + k·(d_x, d_y).
// Differentiating (∂n_x/∂p_x = T/h₂, ∂n_y/∂p_y = −T/h₂, s·d_y − c·q = −1):
//     ∂texel/∂p_x = scale·(1/q, 0),  ∂texel/∂p_y = scale·(−n_x s/q², 1/q²).
// The exact Jacobian: no finite-difference step, and the GLSL camera
// (view.glsl) evaluates the same expressions, so CPU and GPU choose the same
// footprints up to float rounding.
bool Camera::planeFootprint(int px, int py, int exampleSize, double& u, double& v, Jacobian& j) const {
    const double half = std::tan(0.5 * fovDeg * std::numbers::pi / 180.0);
    const double h2 = 0.5 * view.height;
    const double nx = (px + 0.5 - 0.5 * view.width) / h2 * half;
    const double ny = -(py + 0.5 - h2) / h2 * half;
    const double t = tiltDeg * std::numbers::pi / 180.0;
    const double s = std::sin(t), c = std::cos(t);
    const double q = c - ny * s;
    if (q <= 1e-9) return false;  // the ray misses the ground: sky
    const double k = view.scale * h2 / half / q;
    const double tu = view.offsetU + 0.5 * view.width * view.scale + k * nx;
    const double tv = view.offsetV + 0.5 * view.height * view.scale + k * (-s - ny * c);
    if (!std::isfinite(tu) || !std::isfinite(tv) || std::abs(tu) > 1e12 || std::abs(tv) > 1e12) return false;
    const double invW = 1.0 / exampleSize;
    u = tu * invW;
    v = tv * invW;
    const double a = view.scale * invW / q;
    j = Jacobian{a, 0.0, -a * nx * s / q, a / q};
    return true;
}

void validateCamera(const Camera& c) {
    validateView(c.view, "--size/--scale/--offset");
    if (c.kind == Camera::Kind::Plane) {
        if (!std::isfinite(c.tiltDeg) || c.tiltDeg < 0 || c.tiltDeg > 89)
            throw InputError("--tilt must be in [0, 89] degrees");
        if (!std::isfinite(c.fovDeg) || c.fovDeg < 1 || c.fovDeg > 150)
            throw InputError("--fov must be in [1, 150] degrees");
    }
}

}  // namespace stochtex
