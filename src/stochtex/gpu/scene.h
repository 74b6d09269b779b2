#pragma once
// Objects for the `scene` command (paper Fig. 15): meshes with positions,
// normals and texture coordinates, and a look-at camera.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "stochtex/core/enum_names.h"

namespace stochtex {

struct Mesh {
    std::vector<float> vertices;  // x y z, nx ny nz, u v per vertex
    std::vector<uint32_t> indices;
    static constexpr int kStride = 8;
};

// `segments` around the main circle (the other resolutions follow).
Mesh makeSphere(int segments = 128);    // radius 1, uv = (longitude, latitude) in [0,1]²
Mesh makeTorus(int segments = 192);     // radii 1 and 0.35, uv along both circles
Mesh makePlaneMesh(int segments = 64);  // the square [−2, 2]² at y = −1, uv over [0,1]²
// "plane", "sphere" or "torus"; InputError otherwise.
Mesh makeObject(const std::string& name);

// How the pattern lies on a surface: the mesh's texture coordinates, or
// triplanar (three projections along the object's axes, blended by the
// normal: for meshes without uv).
enum class SurfaceMapping { Uv, Triplanar };
inline const EnumNames<SurfaceMapping> kSurfaceMappingNames{{"uv", SurfaceMapping::Uv},
                                                            {"triplanar", SurfaceMapping::Triplanar}};

// Example periods across an object's uv square (scene's --tiling, the web page's objects).
inline constexpr float kDefaultSceneTiling = 4.0f;

using Mat4 = std::array<float, 16>;  // column-major, as OpenGL

struct SceneCamera {
    std::array<float, 3> eye{0.0f, 1.6f, 3.6f}, target{0.0f, -0.1f, 0.0f};
    float fovDeg = 40.0f;
    Mat4 viewProjection(float aspect) const;
};

}  // namespace stochtex
