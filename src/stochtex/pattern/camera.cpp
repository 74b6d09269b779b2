#include "stochtex/pattern/camera.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

// Ground point (in texels) seen through image position (x, y) in pixels
// (continuous, pixel centres at +½). False if the ray misses the plane.
bool planePoint(const Camera& c, double x, double y, double& tu, double& tv) {
    const double half = std::tan(0.5 * c.fovDeg * std::numbers::pi / 180.0);
    const double h2 = 0.5 * c.view.height;
    const double nx = (x - 0.5 * c.view.width) / h2 * half;
    const double ny = -(y - h2) / h2 * half;  // up on screen is positive
    const double t = c.tiltDeg * std::numbers::pi / 180.0;
    // forward (0, −sin t, −cos t), up (0, −cos t, sin t), right (1, 0, 0)
    const double dx = nx, dy = -std::sin(t) - ny * std::cos(t), dz = -std::cos(t) + ny * std::sin(t);
    if (dz >= -1e-9) return false;
    const double height = c.view.scale * h2 / half;  // centre pixel covers `scale` texels at tilt 0
    const double k = height / -dz;
    tu = c.view.offsetU + 0.5 * c.view.width * c.view.scale + k * dx;
    tv = c.view.offsetV + 0.5 * c.view.height * c.view.scale + k * dy;
    return std::isfinite(tu) && std::isfinite(tv) && std::abs(tu) < 1e12 && std::abs(tv) < 1e12;
}

}  // namespace

bool Camera::planeFootprint(int px, int py, int exampleSize, double& u, double& v, Jacobian& j) const {
    const double invW = 1.0 / exampleSize;
    double cu, cv, xu0, xv0, xu1, xv1, yu0, yv0, yu1, yv1;
    const double x = px + 0.5, y = py + 0.5;
    if (!planePoint(*this, x, y, cu, cv) || !planePoint(*this, x - 0.5, y, xu0, xv0) ||
        !planePoint(*this, x + 0.5, y, xu1, xv1) || !planePoint(*this, x, y - 0.5, yu0, yv0) ||
        !planePoint(*this, x, y + 0.5, yu1, yv1))
        return false;
    u = cu * invW;
    v = cv * invW;
    j = Jacobian{(xu1 - xu0) * invW, (xv1 - xv0) * invW, (yu1 - yu0) * invW, (yv1 - yv0) * invW};
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
