// The perspective ground-plane camera: where a pixel's ray meets the
// textured plane and the exact Jacobian of that mapping. Kernel file: GLSL
// and C++, see kernel/glsl.h.
//
// A pixel position p (centres at +½) gives the ray's normalised image
// coordinates n_x = (p_x − w/2)·T/h₂, n_y = −(p_y − h₂)·T/h₂ (h₂ = h/2,
// T = tan(fov/2)). With forward (0, −sin t, −cos t), up (0, −cos t, sin t),
// right (1, 0, 0) the ray is d = (n_x, −s − n_y c, −c + n_y s), s = sin t,
// c = cos t. It meets the ground, H = scale·h₂/T below the eye (at t = 0 a
// pixel covers `scale` texels), at k = H/q, q = −d_z = c − n_y s, i.e.
// k·(d_x, d_y) texels from the point below the view's centre. Differentiating
// (∂n_x/∂p_x = T/h₂, ∂n_y/∂p_y = −T/h₂, s·d_y − c·q = −1):
//     ∂texel/∂p_x = scale·(1/q, 0),  ∂texel/∂p_y = scale·(−n_x s/q², 1/q²).
// The view's offset is added in the host's coordinate precision
// (kernel/coords.h: double on the CPU): planeCentreTexel, below.

// q at or below this: the ray misses the ground (sky).
const float kHorizonSlack = 1e-9f;

struct PlaneRay {
    bool sky;
    vec2 texels;  // k·(d_x, d_y): the ground point from the view's centre point, in texels
    vec2 jx;      // ∂texel/∂p_x
    vec2 jy;      // ∂texel/∂p_y
};

// The ray's normalised image coordinates (n_x, n_y) of pixel position p.
inline vec2 planeImageCoordinates(vec2 p, vec2 viewSize, float tanHalfFov) {
    float h2 = 0.5f * viewSize.y;
    return vec2((p.x - 0.5f * viewSize.x) / h2 * tanHalfFov, -(p.y - h2) / h2 * tanHalfFov);
}

inline PlaneRay planeRay(vec2 p, vec2 viewSize, float scale, float tanHalfFov, float sinTilt, float cosTilt) {
    float h2 = 0.5f * viewSize.y;
    vec2 n = planeImageCoordinates(p, viewSize, tanHalfFov);
    float nx = n.x;
    float ny = n.y;
    float q = cosTilt - ny * sinTilt;
    PlaneRay r;
    r.sky = q <= kHorizonSlack;
    r.texels = vec2(0.0f);
    r.jx = vec2(0.0f);
    r.jy = vec2(0.0f);
    if (r.sky) return r;
    float k = scale * h2 / tanHalfFov / q;
    r.texels = k * vec2(nx, -sinTilt - ny * cosTilt);
    r.jx = vec2(scale / q, 0.0f);
    r.jy = vec2(-scale * nx * sinTilt / q, scale / q) / q;
    return r;
}

// The unit direction from the ground point of pixel p towards the eye,
// −d/|d|, in the texture frame (x along u, y along v, z up): what a shading
// model of the ground sees as its view direction (kernel/lean.glsl).
inline vec3 planeViewDirection(vec2 p, vec2 viewSize, float tanHalfFov, float sinTilt, float cosTilt) {
    vec2 n = planeImageCoordinates(p, viewSize, tanHalfFov);
    vec3 d = vec3(n.x, -sinTilt - n.y * cosTilt, -cosTilt + n.y * sinTilt);
    float len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return vec3(-d.x / len, -d.y / len, -d.z / len);
}

// The zoom view (and every unfiltered render): pixel centre p (pixel index
// + ½) covers texels offset + p·scale, i.e. uv = (offset + p·scale)/W, in
// the host's coordinate precision (kernel/coords.h).
inline coord2 zoomUv(coord2 p, coord2 offset, coord scale, coord invExampleSize) {
    return (offset + p * scale) * invExampleSize;
}

// The plane view's texels are planeRay's, from the ground point below the
// view's centre: offset + (view size / 2)·scale.
inline coord2 planeCentreTexel(coord2 viewSize, coord2 offset, coord scale) {
    return offset + coord(0.5f) * viewSize * scale;
}

// A texture graph's transform of uv (a transform node, composed): the
// matrix rows (m0, m1) and (m2, m3), then the translation; Jacobian
// columns take the linear part alone (transformVector).
inline coord2 transformUv(coord2 uv, coord2 row0, coord2 row1, coord2 t) {
    return coord2(row0.x * uv.x + row0.y * uv.y + t.x, row1.x * uv.x + row1.y * uv.y + t.y);
}
inline coord2 transformVector(coord2 v, coord2 row0, coord2 row1) {
    return coord2(row0.x * v.x + row0.y * v.y, row1.x * v.x + row1.y * v.y);
}
