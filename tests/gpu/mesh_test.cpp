// The scene's user meshes: OBJ and glTF files read into the scene's Mesh,
// centred and scaled to the built-in sphere's size, normals made where the
// file has none, clear refusals of bad files; triplanar mapping for a mesh
// without texture coordinates.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "stochtex/gpu/gpu_graph.h"
#include "stochtex/gpu/mesh_file.h"
#include "stochtex/gpu/scene_render.h"
#include "stochtex/pattern/presets.h"
#include "test_util.h"

namespace stochtex {
namespace {

namespace fs = std::filesystem;

// The folder the tests' mesh files are written to, removed when the
// process ends (the tests read files a test before them wrote only through
// their own writeFile calls).
const fs::path& meshFolder() {
    static const test::ScratchDir dir("stochtex_meshes");
    return dir.path();
}

fs::path writeFile(const std::string& name, const std::string& text) {
    std::ofstream(meshFolder() / name, std::ios::binary) << text;
    return meshFolder() / name;
}

// A cube of side 2 centred on (10, 20, 30): 8 corners, 6 quads (OBJ
// triangulates them), with texture coordinates and face normals when asked.
std::string cubeObj(bool uv, bool normals) {
    std::string s = "# a cube\n";
    for (int k = 0; k < 8; ++k)
        s += "v " + std::to_string(10 + (k & 1 ? 1 : -1)) + " " + std::to_string(20 + (k & 2 ? 1 : -1)) + " " +
             std::to_string(30 + (k & 4 ? 1 : -1)) + "\n";
    s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    s += "vn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\nvn 0 0 -1\nvn 0 0 1\n";
    // Each face's corners (1-based), counter-clockwise seen from outside, and its normal.
    const int faces[6][5] = {{1, 5, 7, 3, 1}, {2, 4, 8, 6, 2}, {1, 2, 6, 5, 3},
                             {3, 7, 8, 4, 4}, {1, 3, 4, 2, 5}, {5, 6, 8, 7, 6}};
    for (const auto& f : faces) {
        s += "f";
        for (int c = 0; c < 4; ++c)
            s += " " + std::to_string(f[c]) + (uv || normals ? "/" : "") + (uv ? std::to_string(c + 1) : "") +
                 (normals ? "/" + std::to_string(f[4]) : "");
        s += "\n";
    }
    return s;
}

TEST(MeshFile, ObjIsTriangulatedCentredAndScaledWithItsUvAndNormals) {
    const LoadedMesh m = loadMesh(writeFile("cube.obj", cubeObj(true, true)).string());
    EXPECT_TRUE(m.hasUv);
    EXPECT_TRUE(m.hasNormals);
    ASSERT_EQ(m.mesh.indices.size(), 36u);  // 6 quads, 2 triangles each
    ASSERT_EQ(m.mesh.vertices.size(), 36u * Mesh::kStride);
    // Centred, half-diagonal 1: the corners at ±1/√3.
    const float corner = 1.0f / std::sqrt(3.0f);
    for (size_t v = 0; v < 36; ++v) {
        const float* p = &m.mesh.vertices[v * Mesh::kStride];
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::abs(p[a]), corner, 1e-6f) << v;
        // The file's face normal points outward: along the axis where the corner is on the face.
        const float dot = p[0] * p[3] + p[1] * p[4] + p[2] * p[5];
        EXPECT_NEAR(dot, corner, 1e-6f) << v;
        EXPECT_TRUE(p[6] == 0.0f || p[6] == 1.0f);
    }
}

// Without normals each corner gets its triangles' area-weighted average,
// pointing out of the cube (within 60° of the diagonal: a quad's two
// triangles meet at two of its corners); without uv the mesh asks for
// triplanar.
TEST(MeshFile, ObjWithoutNormalsOrUvGetsSmoothNormals) {
    const LoadedMesh m = loadMesh(writeFile("bare.obj", cubeObj(false, false)).string());
    EXPECT_FALSE(m.hasUv);
    EXPECT_FALSE(m.hasNormals);
    for (size_t v = 0; v < m.mesh.indices.size(); ++v) {
        const float* p = &m.mesh.vertices[v * Mesh::kStride];
        const float length = std::sqrt(p[3] * p[3] + p[4] * p[4] + p[5] * p[5]);
        EXPECT_NEAR(length, 1.0f, 1e-6f);
        const float outward = (p[0] * p[3] + p[1] * p[4] + p[2] * p[5]) * std::sqrt(3.0f);  // n · p/|p|
        EXPECT_GT(outward, 0.5f) << v;
    }
}

// A glTF quad in a node scaled by 4 and moved: its transform is applied,
// then the mesh centred and scaled as any other; v flipped to OBJ's
// convention (glTF's v runs down the image).
TEST(MeshFile, GltfNodesTransformItsPrimitives) {
    const float data[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,  // positions
                          0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1,  // normals
                          0, 1, 1, 1, 1, 0, 0, 0};             // uv
    const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::string bin(reinterpret_cast<const char*>(data), sizeof data);
    bin += std::string(reinterpret_cast<const char*>(indices), sizeof indices);
    writeFile("quad.bin", bin);
    const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0, "scale": [4, 4, 4], "translation": [5, 0, 0]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
      "buffers": [{"uri": "quad.bin", "byteLength": 140}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 128}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
      "accessors": [
        {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
        {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 0, "byteOffset": 96, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
    const LoadedMesh m = loadMesh(writeFile("quad.gltf", gltf).string());
    EXPECT_TRUE(m.hasUv);
    EXPECT_TRUE(m.hasNormals);
    ASSERT_EQ(m.mesh.indices.size(), 6u);
    // The 4×4 square's corners at ±1/√2 after centring and scaling, normal +z, uv with v flipped.
    const float* second = &m.mesh.vertices[1 * Mesh::kStride];  // corner 1: (1, 0) → (+, −)
    EXPECT_NEAR(second[0], 1.0f / std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(second[1], -1.0f / std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(second[5], 1.0f, 1e-6f);
    EXPECT_EQ(second[6], 1.0f);
    EXPECT_EQ(second[7], 0.0f);  // the file's v = 1
}

// Under a non-uniform scale a normal is not carried as a direction: the
// quad tilted 45° about x in a node scaled (1, 3, 1) keeps its normals
// perpendicular to its edges (the linear part's inverse transpose).
TEST(MeshFile, GltfNormalsStayPerpendicularUnderANonUniformScale) {
    const float data[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::string bin(reinterpret_cast<const char*>(data), sizeof data);
    bin += std::string(reinterpret_cast<const char*>(indices), sizeof indices);
    writeFile("tilted.bin", bin);
    const std::string gltf = R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
      "nodes": [{"scale": [1, 3, 1], "children": [1]}, {"mesh": 0, "rotation": [0.38268343, 0, 0, 0.92387953]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
      "buffers": [{"uri": "tilted.bin", "byteLength": 108}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
      "accessors": [
        {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
        {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
    const LoadedMesh m = loadMesh(writeFile("tilted.gltf", gltf).string());
    EXPECT_FALSE(m.hasUv);
    ASSERT_EQ(m.mesh.indices.size(), 6u);
    const auto vertex = [&](size_t k) { return &m.mesh.vertices[k * Mesh::kStride]; };
    for (size_t k = 0; k < 6; ++k) {
        const float* n = vertex(k) + 3;
        for (const size_t other : {size_t(1), size_t(2)}) {  // the edges from corner 0 of the first triangle
            const float* a = vertex(0);
            const float* b = vertex(other);
            const float dot = n[0] * (b[0] - a[0]) + n[1] * (b[1] - a[1]) + n[2] * (b[2] - a[2]);
            EXPECT_NEAR(dot, 0.0f, 1e-5f) << k;
        }
    }
}

TEST(MeshFile, BadFilesAreRefusedNamingThem) {
    const auto refusal = [](const fs::path& p) {
        return std::string(test::inputErrorOf([&] { loadMesh(p.string()); }).what());
    };
    const fs::path missing = meshFolder() / "nope.obj";
    EXPECT_EQ(refusal(missing), missing.string() + ": no such mesh file");
    const fs::path ply = writeFile("a.ply", "ply\n");
    EXPECT_EQ(refusal(ply), ply.string() + ": unknown mesh format '.ply' (use .obj, .gltf or .glb)");
    const fs::path empty = writeFile("empty.obj", "# nothing\n");
    EXPECT_EQ(refusal(empty), empty.string() + ": the mesh has no triangles");
    const fs::path dangling = writeFile("dangling.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    EXPECT_EQ(refusal(dangling).rfind(dangling.string() + ": ", 0), 0u) << refusal(dangling);
    const fs::path flat = writeFile("point.obj", "v 1 1 1\nf 1 1 1\n");
    EXPECT_EQ(refusal(flat), flat.string() + ": the mesh has no extent");
    const fs::path json = writeFile("bad.gltf", "{ not json");
    EXPECT_EQ(refusal(json).rfind(json.string() + ": not a readable glTF mesh (", 0), 0u) << refusal(json);
    const fs::path glb = writeFile("bad.glb", "glTF");
    EXPECT_EQ(refusal(glb).rfind(glb.string() + ": not a readable glTF mesh (", 0), 0u) << refusal(glb);
}

// A cube with normals but no uv, triplanar: its front face shows the
// pattern (its pixels vary), where uv mapping shows one colour (every uv
// is 0) under the face's one normal.
TEST(MeshFile, TriplanarMappingTexturesAMeshWithoutUv) {
    const LoadedMesh m = loadMesh(writeFile("normals.obj", cubeObj(false, true)).string());
    EXPECT_FALSE(m.hasUv);
    EXPECT_TRUE(m.hasNormals);
    FilterOptions o;
    o.use(parseFilter("smooth"));
    const std::unique_ptr<GpuView> gpu = makeGpuView(loadPreset("camouflage"), test::glContext(), o);
    const auto spread = [&](SurfaceMapping mapping) {
        const Image img = renderScene(*gpu, m.mesh, SceneCamera{}, 192, 128, 4.0f, mapping);
        // 24 × 12 pixels inside the front face (the camera looks down at it).
        std::vector<float> values;
        for (int y = 80; y < 92; ++y)
            for (int x = 84; x < 108; ++x) values.push_back(img.at(x, y, 1));
        const float mean = std::accumulate(values.begin(), values.end(), 0.0f) / float(values.size());
        float var = 0;
        for (const float v : values) var += (v - mean) * (v - mean) / float(values.size());
        return std::sqrt(var);
    };
    const float triplanar = spread(SurfaceMapping::Triplanar), uv = spread(SurfaceMapping::Uv);
    std::printf("[ info ] cube without uv: std of the centre's green %.4f triplanar, %.4f uv\n", triplanar, uv);
    EXPECT_GT(triplanar, 0.01f);
    EXPECT_LT(uv, 0.002f);
    const std::unique_ptr<GpuView> lean = makeGpuView(loadPreset("lean-ridges"), test::glContext(), [] {
        FilterOptions l;
        l.use(parseFilter("smooth"));
        l.response.kind = ResponseKind::Lean;
        return l;
    }());
    EXPECT_EQ(test::inputErrorOf([&] {
                  renderScene(*lean, m.mesh, SceneCamera{}, 16, 16, 4.0f, SurfaceMapping::Triplanar);
              }).parameter(),
              "mapping");
    // The mapping a mesh gets: its uv where it has them, else triplanar; uv refused without them.
    EXPECT_EQ(meshMapping(m, "", "normals.obj"), SurfaceMapping::Triplanar);
    EXPECT_EQ(meshMapping(m, "triplanar", "normals.obj"), SurfaceMapping::Triplanar);
    EXPECT_STREQ(test::inputErrorOf([&] { meshMapping(m, "uv", "normals.obj"); }).what(),
                 "mapping must be triplanar for a mesh without texture coordinates (normals.obj)");
    LoadedMesh withUv = m;
    withUv.hasUv = true;
    EXPECT_EQ(meshMapping(withUv, "", "cube.obj"), SurfaceMapping::Uv);
    EXPECT_EQ(test::inputErrorOf([&] { meshMapping(withUv, "spherical", "cube.obj"); }).parameter(), "mapping");
}

}  // namespace
}  // namespace stochtex
