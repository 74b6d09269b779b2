#pragma once
// A user's mesh for the `scene` command and the workbench's scene view:
// Wavefront OBJ (tinyobjloader) or glTF 2.0 (.gltf / .glb, tinygltf),
// triangulated, with the file's normals and texture coordinates where it
// has them. The mesh is centred on its bounding box and scaled so that the
// box's half-diagonal is 1, the size of the built-in sphere, so the scene's
// camera frames it.
#include <string>

#include "stochtex/gpu/scene.h"

namespace stochtex {

// A mesh file too large to be a scene object (a gigabyte of text, 10⁸
// triangles) is refused before it is parsed or built.
constexpr long long kMaxMeshFileBytes = 512ll << 20;
constexpr long long kMaxMeshTriangles = 16ll << 20;

struct LoadedMesh {
    Mesh mesh;
    // The file had texture coordinates on every vertex (else u = v = 0:
    // the mesh needs triplanar mapping) and normals (else the area-weighted
    // average of its faces' normals at each vertex).
    bool hasUv = false, hasNormals = false;
};

// InputError naming the file for a missing, unreadable, malformed or
// oversized file, an unknown extension, or a mesh without triangles.
LoadedMesh loadMesh(const std::string& path);

// The mapping named (kSurfaceMappingNames), or where `name` is empty the
// mesh's own: uv where it has texture coordinates, else triplanar.
// InputError naming "mapping" for uv on a mesh without them (`path` says which).
SurfaceMapping meshMapping(const LoadedMesh& mesh, const std::string& name, const std::string& path);

}  // namespace stochtex
