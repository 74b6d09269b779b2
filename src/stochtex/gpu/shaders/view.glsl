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

// uv of the pixel at p (gl_FragCoord) and the exact Jacobian of the mapping
// (jx = ∂uv/∂p_x, jy = ∂uv/∂p_y; derivation in camera.cpp), so the built-in
// cameras' footprints match the CPU's. Derivatives need no quad, so this may
// be called under any branch.
vec2 viewUv(vec2 p, out vec2 jx, out vec2 jy, out bool sky) {
    sky = false;
    float a = uScale * uInvW;
    if (!uPlane) {
        jx = vec2(a, 0.0);
        jy = vec2(0.0, a);
        return (uOffset + p * uScale) * uInvW;
    }
    float h2 = 0.5 * uViewSize.y;
    float nx = (p.x - 0.5 * uViewSize.x) / h2 * uTanHalfFov;
    float ny = -(p.y - h2) / h2 * uTanHalfFov;
    float q = uCosTilt - ny * uSinTilt;  // −d_z
    if (q <= 1e-9) {
        sky = true;
        jx = jy = vec2(0.0);
        return vec2(0.0);
    }
    float k = uScale * h2 / uTanHalfFov / q;
    jx = vec2(a / q, 0.0);
    jy = vec2(-a * nx * uSinTilt / q, a / q) / q;
    return (uOffset + 0.5 * uViewSize * uScale + k * vec2(nx, -uSinTilt - ny * uCosTilt)) * uInvW;
}
