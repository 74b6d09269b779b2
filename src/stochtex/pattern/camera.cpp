#include "stochtex/pattern/camera.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"
#include "stochtex/kernel/camera.h"
#include "stochtex/pattern/param_info.h"

namespace stochtex {

// The plane camera: the ray–plane intersection and its exact Jacobian are
// the kernel's (kernel/camera.glsl has the derivation), the same function
// the shaders call, so CPU and GPU choose the same footprints up to float
// rounding; the view's offset is added here in double.
std::array<float, 3> Camera::viewDirection(int px, int py) const {
    if (kind == Kind::Zoom) return {0.0f, 0.0f, 1.0f};
    const double t = tiltDeg * std::numbers::pi / 180.0;
    const kernel::vec3 d = kernel::planeViewDirection(
        kernel::vec2(float(px) + 0.5f, float(py) + 0.5f), kernel::vec2(float(view.width), float(view.height)),
        float(std::tan(0.5 * fovDeg * std::numbers::pi / 180.0)), float(std::sin(t)), float(std::cos(t)));
    return {d.x, d.y, d.z};
}

bool Camera::planeFootprint(int px, int py, int exampleSize, double& u, double& v, Jacobian& j) const {
    const double t = tiltDeg * std::numbers::pi / 180.0;
    const kernel::PlaneRay r = kernel::planeRay(kernel::vec2(float(px) + 0.5f, float(py) + 0.5f),
                                                kernel::vec2(float(view.width), float(view.height)), float(view.scale),
                                                float(std::tan(0.5 * fovDeg * std::numbers::pi / 180.0)),
                                                float(std::sin(t)), float(std::cos(t)));
    if (r.sky) return false;
    const kernel::coord2 centre = kernel::planeCentreTexel(kernel::coord2(view.width, view.height),
                                                           kernel::coord2(view.offsetU, view.offsetV), view.scale);
    const double tu = centre.x + double(r.texels.x);
    const double tv = centre.y + double(r.texels.y);
    if (!std::isfinite(tu) || !std::isfinite(tv) || std::abs(tu) > 1e12 || std::abs(tv) > 1e12) return false;
    const double invW = 1.0 / exampleSize;
    u = tu * invW;
    v = tv * invW;
    j = Jacobian{double(r.jx.x) * invW, double(r.jx.y) * invW, double(r.jy.x) * invW, double(r.jy.y) * invW};
    return true;
}

const ParamInfo& cameraTiltParam() {
    static const ParamInfo p =
        optionParam("tiltDeg", ParamType::Number, "Plane view: tilt from looking straight down, degrees",
                    Camera{}.tiltDeg, 0, 89, "tilt");
    return p;
}

const ParamInfo& cameraFovParam() {
    static const ParamInfo p = optionParam("fovDeg", ParamType::Number, "Plane view: vertical field of view, degrees",
                                           Camera{}.fovDeg, 1, 150, "fov");
    return p;
}

void validateCamera(const Camera& c) {
    validateView(c.view);
    if (c.kind == Camera::Kind::Plane) {
        checkNumber(cameraTiltParam(), c.tiltDeg, " degrees");
        checkNumber(cameraFovParam(), c.fovDeg, " degrees");
    }
}

}  // namespace stochtex
