// The camera (pattern/camera.cpp): pixel centre → uv in example periods.
// Zoom: uv = (offset + p·scale)/W. Plane: the ground point seen through p by
// a pinhole camera tilted by uTilt from looking straight down; `sky` when
// the ray misses the plane.
uniform vec2 uOffset;        // texels
uniform float uScale;        // texels per pixel (at the centre, tilt 0, for the plane)
uniform bool uPlane;
uniform float uTanHalfFov, uSinTilt, uCosTilt;
uniform vec2 uViewSize;      // pixels
uniform vec3 uSky;           // colour of sky pixels

vec2 viewUv(vec2 p, out bool sky) {
    sky = false;
    if (!uPlane) return (uOffset + p * uScale) * uInvW;
    float h2 = 0.5 * uViewSize.y;
    float nx = (p.x - 0.5 * uViewSize.x) / h2 * uTanHalfFov;
    float ny = -(p.y - h2) / h2 * uTanHalfFov;
    float dx = nx, dy = -uSinTilt - ny * uCosTilt, dz = -uCosTilt + ny * uSinTilt;
    if (dz >= -1e-9) {
        sky = true;
        return vec2(0.0);
    }
    float k = uScale * h2 / uTanHalfFov / -dz;
    return (uOffset + 0.5 * uViewSize * uScale + k * vec2(dx, dy)) * uInvW;
}
