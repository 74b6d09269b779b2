#pragma once
// How output pixels see texture space: a centre uv and a Jacobian per pixel.
//
//   zoom  — the View mapping of the unfiltered renderer: uv = (offset +
//           (p + ½)·scale)/W, J = diag(scale/W); footprints are scale×scale
//           texel squares.
//   plane — a pinhole camera (vertical field of view `fovDeg`) above an
//           infinite ground plane carrying the texture, tilted by `tiltDeg`
//           from looking straight down (0° = the zoom view) towards −v, so the
//           horizon rises from the top as the tilt grows. The height is chosen
//           so that at tilt 0 the centre pixel covers `scale` texels. J is the
//           exact derivative of the ray–plane intersection (camera.cpp).
//           Pixels whose ray misses the plane are "sky".
#include <array>
#include <string>

#include "stochtex/core/enum_names.h"
#include "stochtex/filter/footprint.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

struct ParamInfo;

struct Camera {
    enum class Kind { Zoom, Plane };
    static inline const EnumNames<Kind> kKindNames{{"zoom", Kind::Zoom}, {"plane", Kind::Plane}};
    Kind kind = Kind::Zoom;
    View view;            // size, scale (texels per pixel), offset (texels)
    double tiltDeg = 60;  // plane only, in [0, 89]
    double fovDeg = 60;   // plane only

    // Returns false for a sky pixel. exampleSize = W of the pattern.
    bool footprint(int px, int py, int exampleSize, double& u, double& v, Jacobian& j) const {
        if (kind == Kind::Plane) return planeFootprint(px, py, exampleSize, u, v, j);
        const double invW = 1.0 / exampleSize;  // inline: the zoom runs once per pixel of every render
        const std::array<double, 2> uv = pixelUv(view, invW, px, py);
        u = uv[0];
        v = uv[1];
        j = Jacobian{view.scale * invW, 0.0, 0.0, view.scale * invW};
        return true;
    }

    // The unit direction from pixel (px, py)'s ground point towards the eye
    // in the texture frame (x along u, y along v, z up): (0, 0, 1) for the
    // zoom (an orthographic view from above), the kernel's
    // planeViewDirection for the plane.
    std::array<float, 3> viewDirection(int px, int py) const;

private:
    bool planeFootprint(int px, int py, int exampleSize, double& u, double& v, Jacobian& j) const;
};

// The plane view's tilt and field of view, each described once: the range
// validateCamera checks, the flag and help the CLI sets it by.
const ParamInfo& cameraTiltParam();
const ParamInfo& cameraFovParam();
// InputError naming the parameter (tiltDeg, fovDeg, the view's) if the camera is unusable.
void validateCamera(const Camera& c);

}  // namespace stochtex
