// The camera (pattern/camera.cpp): pixel centre → uv in example periods,
// by the kernel's functions (kernel/camera.glsl), as on the CPU.
// Zoom: uv = (offset + p·scale)/W. Plane: the ground point seen through p by
// a pinhole camera tilted by uTilt from looking straight down; `sky` when
// the ray misses the plane.
#include "stochtex/kernel/camera.glsl"
uniform vec2 uOffset;        // texels
uniform float uScale;        // texels per pixel (at the centre, tilt 0, for the plane)
uniform bool uPlane;
uniform float uTanHalfFov, uSinTilt, uCosTilt;
uniform vec2 uViewSize;      // pixels
uniform vec3 uSky;           // colour of sky pixels

// uv of the pixel at p (gl_FragCoord) and the exact Jacobian of the mapping
// (jx = ∂uv/∂p_x, jy = ∂uv/∂p_y): the plane is the kernel's planeRay
// (kernel/camera.glsl), as on the CPU, so the footprints match. Derivatives
// need no quad, so this may be called under any branch.
vec2 viewUv(vec2 p, out vec2 jx, out vec2 jy, out bool sky) {
    sky = false;
    float a = uScale * uPattern.invExampleSize;
    if (!uPlane) {
        jx = vec2(a, 0.0);
        jy = vec2(0.0, a);
        return zoomUv(p, uOffset, uScale, uPattern.invExampleSize);
    }
    PlaneRay r = planeRay(p, uViewSize, uScale, uTanHalfFov, uSinTilt, uCosTilt);
    gEyeDirection = planeViewDirection(p, uViewSize, uTanHalfFov, uSinTilt, uCosTilt);
    sky = r.sky;
    jx = r.jx * uPattern.invExampleSize;
    jy = r.jy * uPattern.invExampleSize;
    return (planeCentreTexel(uViewSize, uOffset, uScale) + r.texels) * uPattern.invExampleSize;
}
