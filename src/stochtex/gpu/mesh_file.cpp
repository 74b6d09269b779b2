#include "stochtex/gpu/mesh_file.h"

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include "stochtex/core/error.h"

namespace stochtex {

namespace {

using Vec3 = std::array<float, 3>;
using Mat4d = std::array<double, 16>;  // column-major, as glTF stores a node's matrix

// Triangles as the loaders find them: per corner a position index into
// `positions` (shared by the faces that meet there, for smooth normals),
// its normal and its uv where the file gives them.
struct Corners {
    std::vector<Vec3> positions;
    std::vector<uint32_t> position;
    std::vector<Vec3> normal;
    std::vector<std::array<float, 2>> uv;
    bool hasNormals = true, hasUv = true;
};

void checkTriangles(const std::string& path, size_t corners) {
    if (corners / 3 > size_t(kMaxMeshTriangles))
        throw InputError(path + ": more than " + std::to_string(kMaxMeshTriangles) + " triangles");
}

Corners readObj(const std::string& path) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
        throw InputError(path + ": not a readable OBJ mesh (" + (why.empty() ? "no reason given" : why) + ")");
    }
    const tinyobj::attrib_t& a = reader.GetAttrib();
    Corners c;
    for (size_t i = 0; i + 2 < a.vertices.size(); i += 3)
        c.positions.push_back({a.vertices[i], a.vertices[i + 1], a.vertices[i + 2]});
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        checkTriangles(path, c.position.size() + shape.mesh.indices.size());
        for (const tinyobj::index_t& k : shape.mesh.indices) {
            if (k.vertex_index < 0 || size_t(k.vertex_index) >= c.positions.size())
                throw InputError(path + ": a face refers to a vertex the file does not have");
            c.position.push_back(uint32_t(k.vertex_index));
            if (k.normal_index >= 0 && size_t(k.normal_index) * 3 + 2 < a.normals.size()) {
                const float* n = &a.normals[size_t(k.normal_index) * 3];
                c.normal.push_back({n[0], n[1], n[2]});
            } else {
                c.hasNormals = false;
                c.normal.push_back({0, 0, 0});
            }
            if (k.texcoord_index >= 0 && size_t(k.texcoord_index) * 2 + 1 < a.texcoords.size()) {
                const float* t = &a.texcoords[size_t(k.texcoord_index) * 2];
                c.uv.push_back({t[0], t[1]});
            } else {
                c.hasUv = false;
                c.uv.push_back({0, 0});
            }
        }
    }
    return c;
}

// A glTF accessor's elements as bytes, element i at data + i·stride, each
// of `components` components of componentBytes, once every element is
// checked to lie inside its buffer view and buffer. what: "an attribute"
// or "indices", for the message.
struct AccessorBytes {
    const unsigned char* data;
    size_t stride, count;
    int componentType, componentBytes;
};
AccessorBytes accessorBytes(const std::string& path, const tinygltf::Model& m, int index, int components,
                            const std::string& what) {
    if (index < 0 || size_t(index) >= m.accessors.size())
        throw InputError(path + ": an accessor index is out of range");
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    const int found = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (found != components)
        throw InputError(path + ": " + what + " of " + std::to_string(found) + " components, expected " +
                         std::to_string(components));
    if (a.bufferView < 0 || size_t(a.bufferView) >= m.bufferViews.size())
        throw InputError(path + ": " + what + " without data (sparse accessors are not read)");
    const tinygltf::BufferView& view = m.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size())
        throw InputError(path + ": a buffer index is out of range");
    const std::vector<unsigned char>& data = m.buffers[size_t(view.buffer)].data;
    const int componentBytes = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (componentBytes <= 0) throw InputError(path + ": " + what + " of an unknown component type");
    const size_t element = size_t(componentBytes) * size_t(components);
    const size_t stride = view.byteStride ? view.byteStride : element;
    const size_t start = view.byteOffset + a.byteOffset;
    if (a.count == 0 || stride < element || start + stride * (a.count - 1) + element > data.size() ||
        a.byteOffset + stride * (a.count - 1) + element > view.byteLength)
        throw InputError(path + ": " + what + " read past their buffer");
    return {data.data() + start, stride, a.count, a.componentType, componentBytes};
}

// An attribute's elements of `components` floats (float, or normalised
// unsigned bytes or shorts for texture coordinates).
std::vector<float> accessorFloats(const std::string& path, const tinygltf::Model& m, int index, int components) {
    const AccessorBytes b = accessorBytes(path, m, index, components, "an attribute");
    std::vector<float> out(b.count * size_t(components));
    for (size_t i = 0; i < b.count; ++i)
        for (int k = 0; k < components; ++k) {
            const unsigned char* p = b.data + i * b.stride + size_t(k * b.componentBytes);
            float v = 0;
            switch (b.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&v, p, 4); break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = float(*p) / 255.0f; break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    uint16_t s = 0;
                    std::memcpy(&s, p, 2);
                    v = float(s) / 65535.0f;
                    break;
                }
                default: throw InputError(path + ": an attribute's component type is not float or normalised");
            }
            out[i * size_t(components) + size_t(k)] = v;
        }
    return out;
}

// A primitive's indices: unsigned bytes, shorts or ints.
std::vector<uint32_t> accessorIndices(const std::string& path, const tinygltf::Model& m, int index) {
    const AccessorBytes b = accessorBytes(path, m, index, 1, "indices");
    if (b.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        b.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        b.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw InputError(path + ": indices are not unsigned integers");
    std::vector<uint32_t> out(b.count);
    for (size_t i = 0; i < b.count; ++i) {
        uint32_t v = 0;
        std::memcpy(&v, b.data + i * b.stride, size_t(b.componentBytes));  // little-endian, as glTF
        out[i] = v;
    }
    return out;
}

Mat4d multiply(const Mat4d& a, const Mat4d& b) {
    Mat4d out{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) out[size_t(c * 4 + r)] += a[size_t(k * 4 + r)] * b[size_t(c * 4 + k)];
    return out;
}

// A node's local transform: its matrix, or T · R · S.
Mat4d localTransform(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        Mat4d m{};
        std::copy(n.matrix.begin(), n.matrix.end(), m.begin());
        return m;
    }
    const double x = n.rotation.size() == 4 ? n.rotation[0] : 0, y = n.rotation.size() == 4 ? n.rotation[1] : 0,
                 z = n.rotation.size() == 4 ? n.rotation[2] : 0, w = n.rotation.size() == 4 ? n.rotation[3] : 1;
    const double sx = n.scale.size() == 3 ? n.scale[0] : 1, sy = n.scale.size() == 3 ? n.scale[1] : 1,
                 sz = n.scale.size() == 3 ? n.scale[2] : 1;
    Mat4d m = {(1 - 2 * (y * y + z * z)) * sx,
               2 * (x * y + z * w) * sx,
               2 * (x * z - y * w) * sx,
               0,
               2 * (x * y - z * w) * sy,
               (1 - 2 * (x * x + z * z)) * sy,
               2 * (y * z + x * w) * sy,
               0,
               2 * (x * z + y * w) * sz,
               2 * (y * z - x * w) * sz,
               (1 - 2 * (x * x + y * y)) * sz,
               0,
               0,
               0,
               0,
               1};
    if (n.translation.size() == 3) m[12] = n.translation[0], m[13] = n.translation[1], m[14] = n.translation[2];
    return m;
}

// The files a glTF reads (its buffers): regular files of bounded size,
// named as written (no shell expansion of `~` or `$VAR`); nothing written.
tinygltf::FsCallbacks boundedFiles() {
    tinygltf::FsCallbacks fs{};
    fs.FileExists = [](const std::string& path, void*) {
        std::error_code ec;
        return std::filesystem::is_regular_file(path, ec);
    };
    fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
    fs.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
        std::error_code ec;
        const bool regular = std::filesystem::is_regular_file(path, ec);
        const auto bytes = regular ? std::filesystem::file_size(path, ec) : 0;
        if (!regular || ec || (long long)bytes > kMaxMeshFileBytes) {
            if (err)
                *err += path + ": not a regular file of at most " + std::to_string(kMaxMeshFileBytes >> 20) + " MB";
            return false;
        }
        std::ifstream in(path, std::ios::binary);
        out->resize(size_t(bytes));
        if (bytes && !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(bytes))) {
            if (err) *err += path + ": cannot be read";
            return false;
        }
        return true;
    };
    fs.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
        if (err) *err += "a mesh file is only read";
        return false;
    };
    return fs;
}

Corners readGltf(const std::string& path, bool binary) {
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(boundedFiles());
    // The mesh's images are not read: the pattern is its texture.
    loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*,
                             int, void*) { return true; },
                          nullptr);
    tinygltf::Model m;
    std::string error, warning;
    const bool ok = binary ? loader.LoadBinaryFromFile(&m, &error, &warning, path)
                           : loader.LoadASCIIFromFile(&m, &error, &warning, path);
    if (!ok) {
        while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
        throw InputError(path + ": not a readable glTF mesh (" + (error.empty() ? "no reason given" : error) + ")");
    }
    Corners c;
    const auto addMesh = [&](const tinygltf::Mesh& mesh, const Mat4d& transform) {
        const auto point = [&](const float* p, double w) {
            Vec3 out{};
            for (int r = 0; r < 3; ++r)
                out[size_t(r)] = float(transform[size_t(r)] * p[0] + transform[size_t(4 + r)] * p[1] +
                                       transform[size_t(8 + r)] * p[2] + transform[size_t(12 + r)] * w);
            return out;
        };
        // Normals by the cofactor matrix of the linear part (its inverse
        // transpose times the determinant, the determinant's sign undone):
        // right under non-uniform scales; lengths are normalised later.
        const auto at = [&](int r, int c) { return transform[size_t(((c % 3) * 4) + (r % 3))]; };
        std::array<double, 9> cofactor{};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                cofactor[size_t(r * 3 + c)] = at(r + 1, c + 1) * at(r + 2, c + 2) - at(r + 1, c + 2) * at(r + 2, c + 1);
        const double det = at(0, 0) * cofactor[0] + at(0, 1) * cofactor[1] + at(0, 2) * cofactor[2];
        const double sign = det < 0 ? -1.0 : 1.0;
        const auto normal = [&](const float* v) {
            Vec3 out{};
            for (int r = 0; r < 3; ++r)
                out[size_t(r)] = float(sign * (cofactor[size_t(r * 3)] * v[0] + cofactor[size_t(r * 3 + 1)] * v[1] +
                                               cofactor[size_t(r * 3 + 2)] * v[2]));
            return out;
        };
        for (const tinygltf::Primitive& prim : mesh.primitives) {
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;  // points and lines: no surface
            const auto position = prim.attributes.find("POSITION");
            if (position == prim.attributes.end()) continue;
            const std::vector<float> p = accessorFloats(path, m, position->second, 3);
            const size_t vertices = p.size() / 3;
            std::vector<float> n, uv;
            if (const auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end())
                n = accessorFloats(path, m, it->second, 3);
            if (const auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end())
                uv = accessorFloats(path, m, it->second, 2);
            std::vector<uint32_t> indices;
            if (prim.indices >= 0) {
                indices = accessorIndices(path, m, prim.indices);
            } else {
                indices.resize(vertices);
                for (size_t i = 0; i < vertices; ++i) indices[i] = uint32_t(i);
            }
            checkTriangles(path, c.position.size() + indices.size());
            const uint32_t first = uint32_t(c.positions.size());
            for (size_t i = 0; i < vertices; ++i) c.positions.push_back(point(&p[3 * i], 1.0));
            for (size_t t = 0; t + 2 < indices.size(); t += 3)
                for (size_t k = t; k < t + 3; ++k) {
                    const uint32_t v = indices[k];
                    if (v >= vertices) throw InputError(path + ": an index refers to a vertex the mesh does not have");
                    c.position.push_back(first + v);
                    if (n.size() == 3 * vertices) {
                        c.normal.push_back(normal(&n[3 * v]));
                    } else {
                        c.hasNormals = false;
                        c.normal.push_back({0, 0, 0});
                    }
                    if (uv.size() == 2 * vertices) {
                        c.uv.push_back({uv[2 * v], 1.0f - uv[2 * v + 1]});  // glTF's v runs down the image
                    } else {
                        c.hasUv = false;
                        c.uv.push_back({0, 0});
                    }
                }
        }
    };
    const std::function<void(int, const Mat4d&, int)> visit = [&](int node, const Mat4d& parent, int depth) {
        if (node < 0 || size_t(node) >= m.nodes.size() || depth > 64)
            throw InputError(path + ": a node index is out of range or the node tree is too deep");
        const tinygltf::Node& n = m.nodes[size_t(node)];
        const Mat4d transform = multiply(parent, localTransform(n));
        if (n.mesh >= 0 && size_t(n.mesh) < m.meshes.size()) addMesh(m.meshes[size_t(n.mesh)], transform);
        for (const int child : n.children) visit(child, transform, depth + 1);
    };
    const Mat4d identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (!m.scenes.empty()) {
        const size_t scene =
            m.defaultScene >= 0 && size_t(m.defaultScene) < m.scenes.size() ? size_t(m.defaultScene) : 0;
        for (const int node : m.scenes[scene].nodes) visit(node, identity, 0);
    } else {
        for (const tinygltf::Mesh& mesh : m.meshes) addMesh(mesh, identity);
    }
    return c;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalized(const Vec3& v) {
    const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return l > 0 ? Vec3{v[0] / l, v[1] / l, v[2] / l} : Vec3{0, 1, 0};
}

}  // namespace

SurfaceMapping meshMapping(const LoadedMesh& mesh, const std::string& name, const std::string& path) {
    const SurfaceMapping m = name.empty() ? (mesh.hasUv ? SurfaceMapping::Uv : SurfaceMapping::Triplanar)
                                          : parseEnum(kSurfaceMappingNames, name, "mapping");
    if (m == SurfaceMapping::Uv && !mesh.hasUv)
        throw InputError::parameter("mapping",
                                    "must be triplanar for a mesh without texture coordinates (" + path + ")");
    return m;
}

LoadedMesh loadMesh(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": no such mesh file");
    const auto bytes = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot read the mesh file");
    if ((long long)bytes > kMaxMeshFileBytes)
        throw InputError(path + ": mesh file larger than " + std::to_string(kMaxMeshFileBytes >> 20) + " MB");
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
        throw InputError(path + ": unknown mesh format '" + ext + "' (use .obj, .gltf or .glb)");
    if (bytes == 0) throw InputError(path + ": empty mesh file");
    Corners c;
    try {
        c = ext == ".obj" ? readObj(path) : readGltf(path, ext == ".glb");
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        // The parsers' own checks (tinygltf indexes some vectors with at()).
        throw InputError(path + ": not a readable mesh file (" + e.what() + ")");
    }
    if (c.position.size() < 3) throw InputError(path + ": the mesh has no triangles");
    // Centred on its bounding box, scaled to a half-diagonal of 1.
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const uint32_t k : c.position)
        for (size_t a = 0; a < 3; ++a) {
            const float v = c.positions[k][a];
            if (!std::isfinite(v)) throw InputError(path + ": a vertex position is not finite");
            lo[a] = std::min(lo[a], v), hi[a] = std::max(hi[a], v);
        }
    const Vec3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    const float half = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                 (hi[2] - lo[2]) * (hi[2] - lo[2])) /
                       2;
    if (!(half > 0) || !std::isfinite(half)) throw InputError(path + ": the mesh has no extent");
    // Smooth normals where the file has none: each position's faces' normals, weighted by their areas.
    std::vector<Vec3> smooth;
    if (!c.hasNormals) {
        smooth.assign(c.positions.size(), Vec3{0, 0, 0});
        for (size_t t = 0; t + 2 < c.position.size(); t += 3) {
            const Vec3& a = c.positions[c.position[t]];
            const Vec3 n = cross(sub(c.positions[c.position[t + 1]], a), sub(c.positions[c.position[t + 2]], a));
            for (size_t k = t; k < t + 3; ++k)
                for (size_t i = 0; i < 3; ++i) smooth[c.position[k]][i] += n[i];
        }
    }
    LoadedMesh out;
    out.hasUv = c.hasUv;
    out.hasNormals = c.hasNormals;
    out.mesh.vertices.reserve(c.position.size() * Mesh::kStride);
    for (size_t k = 0; k < c.position.size(); ++k) {
        const Vec3& p = c.positions[c.position[k]];
        const Vec3 n = normalized(c.hasNormals ? c.normal[k] : smooth[c.position[k]]);
        out.mesh.vertices.insert(out.mesh.vertices.end(),
                                 {(p[0] - centre[0]) / half, (p[1] - centre[1]) / half, (p[2] - centre[2]) / half, n[0],
                                  n[1], n[2], c.uv[k][0], c.uv[k][1]});
        out.mesh.indices.push_back(uint32_t(k));
    }
    return out;
}

}  // namespace stochtex
