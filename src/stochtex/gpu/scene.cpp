#include "stochtex/gpu/scene.h"

#include <cmath>
#include <numbers>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

// A (u, v) grid wrapped onto a surface: f(u, v) gives position and normal.
template <class F>
Mesh grid(int nu, int nv, F&& f) {
    Mesh m;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            const float u = float(i) / float(nu), v = float(j) / float(nv);
            std::array<float, 3> p{}, n{};
            f(u, v, p, n);
            m.vertices.insert(m.vertices.end(), {p[0], p[1], p[2], n[0], n[1], n[2], u, v});
        }
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const uint32_t a = uint32_t(j * (nu + 1) + i), b = a + 1, c = a + uint32_t(nu + 1), d = c + 1;
            m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    return m;
}

constexpr float kTau = 2.0f * std::numbers::pi_v<float>;

}  // namespace

Mesh makeSphere(int segments) {
    return grid(segments, segments / 2, [](float u, float v, auto& p, auto& n) {
        const float phi = kTau * u, theta = std::numbers::pi_v<float> * v;
        n = {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
        p = n;
    });
}

Mesh makeTorus(int segments) {
    return grid(segments, segments / 3, [](float u, float v, auto& p, auto& n) {
        const float a = kTau * u, b = kTau * v, big = 1.0f, small = 0.35f;
        n = {std::cos(b) * std::cos(a), std::sin(b), std::cos(b) * std::sin(a)};
        p = {(big + small * std::cos(b)) * std::cos(a), small * std::sin(b), (big + small * std::cos(b)) * std::sin(a)};
    });
}

Mesh makePlaneMesh(int segments) {
    return grid(segments, segments, [](float u, float v, auto& p, auto& n) {
        p = {-2.0f + 4.0f * u, -1.0f, -2.0f + 4.0f * v};
        n = {0.0f, 1.0f, 0.0f};
    });
}

Mesh makeObject(const std::string& name) {
    if (name == "sphere") return makeSphere();
    if (name == "torus") return makeTorus();
    if (name == "plane") return makePlaneMesh();
    throw InputError::parameter("object", "must be plane, sphere or torus, got \"" + name + "\"");
}

Mat4 SceneCamera::viewProjection(float aspect) const {
    // look-at
    std::array<float, 3> f{target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    auto normalize = [](std::array<float, 3> v) {
        const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return std::array<float, 3>{v[0] / l, v[1] / l, v[2] / l};
    };
    auto cross = [](const std::array<float, 3>& a, const std::array<float, 3>& b) {
        return std::array<float, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    f = normalize(f);
    const auto s = normalize(cross(f, {0.0f, 1.0f, 0.0f}));
    const auto u = cross(s, f);
    auto dot = [](const std::array<float, 3>& a, const std::array<float, 3>& b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const Mat4 view = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
                       -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
    const float t = 1.0f / std::tan(0.5f * fovDeg * std::numbers::pi_v<float> / 180.0f);
    const float zn = 0.05f, zf = 50.0f;
    const Mat4 proj = {t / aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, (zf + zn) / (zn - zf), -1, 0, 0, 2 * zf * zn / (zn - zf), 0};
    Mat4 out{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            float v = 0;
            for (int k = 0; k < 4; ++k) v += proj[size_t(k * 4 + r)] * view[size_t(c * 4 + k)];
            out[size_t(c * 4 + r)] = v;
        }
    return out;
}

}  // namespace stochtex
