// SPDX-License-Identifier: MIT
// glTF 2.0 (.gltf JSON, .glb binary) through tinygltf. Read: every triangle primitive (modes TRIANGLES,
// TRIANGLE_STRIP, TRIANGLE_FAN; points and lines are skipped, as in Open3D) of every mesh instance of the
// default scene, placed by its node's world transform; POSITION, NORMAL, COLOR_0 and TEXCOORD_0 are kept
// when every primitive has them. Each material becomes one texture (its decoded PNG/JPEG base colour image,
// empty without one) when any material has an image, and each triangle its primitive's material id.
// Written: one mesh, float32 positions, normals and COLOR_0, uint32 indices, data embedded.
// tinygltf checks the JSON; every accessor, view and index is checked here again before it is followed.
#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "o3d/io/byte_reader.h"
#include "o3d/io/image_io.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {
namespace {

// Memory input must be self-contained: no file is opened on its behalf.
bool no_file_exists(const std::string&, void*) { return false; }
std::string same_path(const std::string& p, void*) { return p; }
bool no_read(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err) *err += "'" + path + "' is not read: in-memory glTF must embed its data\n";
    return false;
}
bool no_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing files is not allowed here\n";
    return false;
}
/// @brief tinygltf's image callback: decode PNG/JPEG into the vector of images `user` points to, at the
/// image's index. A broken image is a warning, not a failure: the geometry stays readable.
bool decode_image(tinygltf::Image*, const int index, std::string*, std::string* warn, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto& images = *static_cast<std::vector<geometry::Image>*>(user);
    if (index < 0 || size <= 0) return true;
    if (images.size() <= static_cast<size_t>(index)) images.resize(static_cast<size_t>(index) + 1);
    const bool jpeg = size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
    try {
        images[static_cast<size_t>(index)] = read_image_from_memory(bytes, static_cast<size_t>(size), jpeg ? "jpg" : "png");
    } catch (const std::exception& e) {
        if (warn) *warn += "image " + std::to_string(index) + " not decoded: " + e.what() + "\n";
    }
    return true;
}

class GltfReader {
public:
    GltfReader(const Input& in, const tinygltf::Model& model, std::vector<geometry::Image>& images)
        : in_(in), model_(model), images_(images) {}

    geometry::TriangleMesh read() {
        if (!model_.scenes.empty()) {
            const int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (s >= static_cast<int>(model_.scenes.size())) fail("the default scene " + std::to_string(s) + " does not exist");
            visit(model_.scenes[static_cast<size_t>(s)].nodes);
        } else if (!model_.nodes.empty()) {
            for (size_t n = 0; n < model_.nodes.size(); ++n)
                if (model_.nodes[n].mesh >= 0) add_mesh(model_.nodes[n].mesh, local(model_.nodes[n]));
        } else {
            for (size_t m = 0; m < model_.meshes.size(); ++m) add_mesh(static_cast<int>(m), Eigen::Matrix4d::Identity());
        }
        if (!all_normals_) mesh_.vertex_normals.clear();
        if (!all_colors_) mesh_.vertex_colors.clear();
        if (!all_uvs_) mesh_.triangle_uvs.clear();
        if (model_.materials.empty()) mesh_.triangle_material_ids.clear();
        add_textures();
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& why) { parse_error(in_, "glTF: " + why); }

    /// @brief One texture per material: its base colour image, or an empty one.
    void add_textures() {
        std::vector<geometry::Image> textures;
        bool any = false;
        for (const tinygltf::Material& m : model_.materials) {
            const int t = m.pbrMetallicRoughness.baseColorTexture.index;
            const int source = t >= 0 && t < static_cast<int>(model_.textures.size())
                                   ? model_.textures[static_cast<size_t>(t)].source
                                   : -1;
            if (source >= 0 && static_cast<size_t>(source) < images_.size() && !images_[static_cast<size_t>(source)].empty()) {
                textures.push_back(std::move(images_[static_cast<size_t>(source)]));
                any = true;
            } else {
                textures.emplace_back();
            }
        }
        if (any) mesh_.textures = std::move(textures);
    }

    Eigen::Matrix4d local(const tinygltf::Node& n) {
        Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
        if (n.matrix.size() == 16) {
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m(r, c) = n.matrix[static_cast<size_t>(4 * c + r)];  // column-major
            return m;
        }
        if (n.translation.size() == 3) m.block<3, 1>(0, 3) = Eigen::Vector3d(n.translation[0], n.translation[1], n.translation[2]);
        Eigen::Matrix3d rs = Eigen::Matrix3d::Identity();
        if (n.rotation.size() == 4) {
            Eigen::Quaterniond q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
            if (q.norm() > 0) rs = q.normalized().toRotationMatrix();
        }
        if (n.scale.size() == 3) rs = rs * Eigen::Vector3d(n.scale[0], n.scale[1], n.scale[2]).asDiagonal();
        m.block<3, 3>(0, 0) = rs;
        return m;
    }

    /// @brief Walk the node trees under `roots` depth first (children in order), placing each mesh by its
    /// world transform. An explicit stack, and each node visited once: glTF nodes form trees, so a cycle or
    /// a node with two parents is an error rather than deep recursion or exponential instancing.
    void visit(const std::vector<int>& roots) {
        std::vector<char> seen(model_.nodes.size(), 0);
        std::vector<std::pair<int, Eigen::Matrix4d>> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, Eigen::Matrix4d::Identity());
        while (!stack.empty()) {
            const int node = stack.back().first;
            const Eigen::Matrix4d parent = stack.back().second;
            stack.pop_back();
            if (node < 0 || node >= static_cast<int>(model_.nodes.size()))
                fail("a scene names the missing node " + std::to_string(node));
            if (seen[static_cast<size_t>(node)]++)
                fail("node " + std::to_string(node) + " is reached twice (a cycle, or a node with two parents)");
            const tinygltf::Node& n = model_.nodes[static_cast<size_t>(node)];
            const Eigen::Matrix4d world = parent * local(n);
            if (n.mesh >= 0) add_mesh(n.mesh, world);
            for (auto it = n.children.rbegin(); it != n.children.rend(); ++it) stack.emplace_back(*it, world);
        }
    }

    /// @brief The accessor's values as doubles, `components` per item (integers normalised when asked).
    std::vector<double> values(int index, int components, bool normalize, const char* what) {
        if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
            fail(std::string(what) + " names the missing accessor " + std::to_string(index));
        const tinygltf::Accessor& a = model_.accessors[static_cast<size_t>(index)];
        if (a.sparse.isSparse) fail(std::string(what) + ": sparse accessors are not supported");
        const int have = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
        if (have != components) fail(std::string(what) + ": accessor " + std::to_string(index) + " has " +
                                     std::to_string(have) + " components, expected " + std::to_string(components));
        ScalarType t;
        switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_BYTE: t = ScalarType::Int8; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: t = ScalarType::UInt8; break;
            case TINYGLTF_COMPONENT_TYPE_SHORT: t = ScalarType::Int16; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: t = ScalarType::UInt16; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: t = ScalarType::UInt32; break;
            case TINYGLTF_COMPONENT_TYPE_FLOAT: t = ScalarType::Float32; break;
            default: fail(std::string(what) + ": unknown component type " + std::to_string(a.componentType));
        }
        const size_t item = scalar_size(t) * static_cast<size_t>(components);
        if (a.count == 0) return {};
        if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model_.bufferViews.size()))
            fail(std::string(what) + ": accessor " + std::to_string(index) + " has no valid bufferView");
        const tinygltf::BufferView& v = model_.bufferViews[static_cast<size_t>(a.bufferView)];
        if (v.buffer < 0 || v.buffer >= static_cast<int>(model_.buffers.size()))
            fail(std::string(what) + ": bufferView " + std::to_string(a.bufferView) + " names a missing buffer");
        const std::vector<unsigned char>& data = model_.buffers[static_cast<size_t>(v.buffer)].data;
        const size_t stride = v.byteStride ? v.byteStride : item;
        if (stride < item) fail(std::string(what) + ": byteStride " + std::to_string(stride) + " is below the item size");
        if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset || a.byteOffset > v.byteLength ||
            item > v.byteLength - a.byteOffset || (a.count - 1) > (v.byteLength - a.byteOffset - item) / stride)
            fail(std::string(what) + ": accessor " + std::to_string(index) + " reaches past its buffer");
        const uint8_t* base = data.data() + v.byteOffset + a.byteOffset;
        double scale = 1.0;
        if (normalize && t != ScalarType::Float32) {
            switch (t) {
                case ScalarType::Int8: scale = 127.0; break;
                case ScalarType::UInt8: scale = 255.0; break;
                case ScalarType::Int16: scale = 32767.0; break;
                case ScalarType::UInt16: scale = 65535.0; break;
                default: scale = 4294967295.0;
            }
        }
        std::vector<double> out(a.count * static_cast<size_t>(components));
        for (size_t i = 0; i < a.count; ++i)
            for (int c = 0; c < components; ++c)
                out[i * static_cast<size_t>(components) + static_cast<size_t>(c)] =
                    load_as_double(base + i * stride + static_cast<size_t>(c) * scalar_size(t), t, !kHostLittleEndian) / scale;
        return out;
    }

    int attribute(const tinygltf::Primitive& p, const char* name) {
        const auto it = p.attributes.find(name);
        return it == p.attributes.end() ? -1 : it->second;
    }

    void add_mesh(int index, const Eigen::Matrix4d& world) {
        if (index >= static_cast<int>(model_.meshes.size())) fail("a node names the missing mesh " + std::to_string(index));
        for (const tinygltf::Primitive& p : model_.meshes[static_cast<size_t>(index)].primitives) add_primitive(p, world);
    }

    void add_primitive(const tinygltf::Primitive& p, const Eigen::Matrix4d& world) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP && p.mode != TINYGLTF_MODE_TRIANGLE_FAN)
            return;
        const int pos = attribute(p, "POSITION");
        if (pos < 0) fail("a triangle primitive has no POSITION");
        const std::vector<double> xyz = values(pos, 3, false, "POSITION");
        const size_t n = xyz.size() / 3;
        const size_t base = mesh_.vertices.size();
        if (base + n > static_cast<size_t>(INT32_MAX)) fail("more vertices than a mesh can index");

        const Eigen::Matrix3d linear = world.block<3, 3>(0, 0);
        const Eigen::Matrix3d normal_matrix = linear.inverse().transpose();
        for (size_t i = 0; i < n; ++i)
            mesh_.vertices.push_back(linear * Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]) +
                                     world.block<3, 1>(0, 3));

        const int nrm = attribute(p, "NORMAL");
        all_normals_ = all_normals_ && nrm >= 0;
        if (all_normals_) {
            const std::vector<double> v = values(nrm, 3, false, "NORMAL");
            if (v.size() != xyz.size()) fail("NORMAL and POSITION counts differ");
            for (size_t i = 0; i < n; ++i) {
                Eigen::Vector3d w = normal_matrix * Eigen::Vector3d(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
                const double len = w.norm();
                mesh_.vertex_normals.push_back(len > 0 && std::isfinite(len) ? Eigen::Vector3d(w / len) : w);
            }
        }
        const int col = attribute(p, "COLOR_0");
        all_colors_ = all_colors_ && col >= 0;
        if (all_colors_) {
            if (col >= static_cast<int>(model_.accessors.size())) fail("COLOR_0 names a missing accessor");
            const int components =
                tinygltf::GetNumComponentsInType(static_cast<uint32_t>(model_.accessors[static_cast<size_t>(col)].type));
            const std::vector<double> v = values(col, components == 4 ? 4 : 3, true, "COLOR_0");
            const size_t stride = components == 4 ? 4 : 3;
            if (v.size() / stride != n) fail("COLOR_0 and POSITION counts differ");
            for (size_t i = 0; i < n; ++i) mesh_.vertex_colors.emplace_back(v[stride * i], v[stride * i + 1], v[stride * i + 2]);
        }

        std::vector<size_t> idx;
        if (p.indices >= 0) {
            const std::vector<double> v = values(p.indices, 1, false, "indices");
            idx.resize(v.size());
            for (size_t i = 0; i < v.size(); ++i) {
                if (!(v[i] >= 0 && v[i] < static_cast<double>(n)))
                    fail("index " + std::to_string(v[i]) + " is outside the primitive's " + std::to_string(n) + " vertices");
                idx[i] = static_cast<size_t>(v[i]);
            }
        } else {
            idx.resize(n);
            for (size_t i = 0; i < n; ++i) idx[i] = i;
        }
        std::vector<std::array<size_t, 3>> tris;
        if (p.mode == TINYGLTF_MODE_TRIANGLES) {
            for (size_t i = 0; i + 2 < idx.size(); i += 3) tris.push_back({idx[i], idx[i + 1], idx[i + 2]});
        } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < idx.size(); ++i)
                tris.push_back(i % 2 ? std::array<size_t, 3>{idx[i + 1], idx[i], idx[i + 2]}
                                     : std::array<size_t, 3>{idx[i], idx[i + 1], idx[i + 2]});
        } else {
            for (size_t i = 1; i + 1 < idx.size(); ++i) tris.push_back({idx[0], idx[i], idx[i + 1]});
        }
        for (const auto& t : tris)
            mesh_.triangles.emplace_back(static_cast<int>(base + t[0]), static_cast<int>(base + t[1]), static_cast<int>(base + t[2]));
        const int material = p.material >= 0 && p.material < static_cast<int>(model_.materials.size()) ? p.material : -1;
        mesh_.triangle_material_ids.insert(mesh_.triangle_material_ids.end(), tris.size(), material);

        const int uv = attribute(p, "TEXCOORD_0");
        all_uvs_ = all_uvs_ && uv >= 0;
        if (all_uvs_) {
            const std::vector<double> v = values(uv, 2, true, "TEXCOORD_0");
            if (v.size() / 2 != n) fail("TEXCOORD_0 and POSITION counts differ");
            for (const auto& t : tris)
                for (size_t c : t) mesh_.triangle_uvs.emplace_back(v[2 * c], v[2 * c + 1]);
        }
    }

    const Input& in_;
    const tinygltf::Model& model_;
    std::vector<geometry::Image>& images_;
    geometry::TriangleMesh mesh_;
    bool all_normals_ = true, all_colors_ = true, all_uvs_ = true;
};

/// @brief Append `bytes` to the buffer (4-byte aligned) as a new view, and an accessor over it.
int add_accessor(tinygltf::Model& model, const void* bytes, size_t size, int component, int type, size_t count,
                 int target) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    while (data.size() % 4) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    data.insert(data.end(), static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
    model.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    a.componentType = component;
    a.type = type;
    a.count = count;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size() - 1);
}

int add_vec3(tinygltf::Model& model, const std::vector<Eigen::Vector3d>& v, bool bounds) {
    std::vector<float> f(3 * v.size());
    for (size_t i = 0; i < v.size(); ++i)
        for (int k = 0; k < 3; ++k) f[3 * i + static_cast<size_t>(k)] = static_cast<float>(v[i][k]);
    const int a = add_accessor(model, f.data(), f.size() * sizeof(float), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                               v.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
    if (bounds && !v.empty()) {  // POSITION requires min and max
        std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
        for (size_t i = 0; i < v.size(); ++i)
            for (size_t k = 0; k < 3; ++k) {
                lo[k] = std::min<double>(lo[k], f[3 * i + k]);
                hi[k] = std::max<double>(hi[k], f[3 * i + k]);
            }
        model.accessors[static_cast<size_t>(a)].minValues = lo;
        model.accessors[static_cast<size_t>(a)].maxValues = hi;
    }
    return a;
}

}  // namespace

geometry::TriangleMesh read_mesh_gltf(const Input& in, const Sidecars& sidecars, bool binary) {
    tinygltf::TinyGLTF loader;
    std::vector<geometry::Image> images;
    loader.SetImageLoader(decode_image, &images);
    if (!sidecars.from_file) loader.SetFsCallbacks(tinygltf::FsCallbacks{no_file_exists, same_path, no_read, no_write, nullptr});
    if (in.size > UINT32_MAX) parse_error(in, "glTF: larger than 4 GiB");
    tinygltf::Model model;
    std::string err, warn;
    const std::string base = sidecars.directory.empty() ? "." : sidecars.directory;
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, in.data, static_cast<unsigned>(in.size), base)
                           : loader.LoadASCIIFromString(&model, &err, &warn, in.chars(), static_cast<unsigned>(in.size), base);
    if (!ok) parse_error(in, std::string(binary ? "GLB" : "glTF") + ": " + (err.empty() ? "tinygltf failed" : err));
    geometry::TriangleMesh mesh = GltfReader(in, model, images).read();
    check_face_indices(in, mesh);
    return mesh;
}

std::vector<uint8_t> write_mesh_gltf(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options, bool binary) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "o3d";
    std::ostringstream os;
    tinygltf::TinyGLTF writer;
    if (mesh.vertices.empty()) {  // a GLB may not carry an empty BIN chunk: an empty scene then
        model.scenes.emplace_back();
        model.scenes[0].name = "empty";  // tinygltf writes a scene without members as null, which it refuses
        model.defaultScene = 0;
        if (!writer.WriteGltfSceneToStream(&model, os, !binary, binary)) throw IoError("glTF: tinygltf could not encode the mesh");
        const std::string s = os.str();
        return std::vector<uint8_t>(s.begin(), s.end());
    }
    model.buffers.emplace_back();
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.attributes["POSITION"] = add_vec3(model, mesh.vertices, true);
    if (options.write_vertex_normals && mesh.has_vertex_normals())
        prim.attributes["NORMAL"] = add_vec3(model, mesh.vertex_normals, false);
    if (options.write_vertex_colors && mesh.has_vertex_colors())
        prim.attributes["COLOR_0"] = add_vec3(model, mesh.vertex_colors, false);
    std::vector<uint32_t> idx(3 * mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) idx[3 * t + static_cast<size_t>(k)] = static_cast<uint32_t>(mesh.triangles[t][k]);
    prim.indices = add_accessor(model, idx.data(), idx.size() * sizeof(uint32_t), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                TINYGLTF_TYPE_SCALAR, idx.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Mesh m;
    m.primitives.push_back(prim);
    model.meshes.push_back(m);
    tinygltf::Node node;
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    if (!writer.WriteGltfSceneToStream(&model, os, !binary, binary)) throw IoError("glTF: tinygltf could not encode the mesh");
    const std::string s = os.str();
    return std::vector<uint8_t>(s.begin(), s.end());
}

}  // namespace o3d::io::detail
