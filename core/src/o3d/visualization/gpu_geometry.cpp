// SPDX-License-Identifier: MIT
#include "o3d/visualization/gpu_geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

struct Vertex {
    float position[3];
    float normal[3];
    float color[3];
};

Vertex vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Eigen::Vector3d& c) {
    return {{float(p.x()), float(p.y()), float(p.z())},
            {float(n.x()), float(n.y()), float(n.z())},
            {float(c.x()), float(c.y()), float(c.z())}};
}

VertexBuffer make_buffer(const std::vector<Vertex>& vertices, const std::vector<uint32_t>* indices = nullptr) {
    VertexBuffer b;
    glGenVertexArrays(1, &b.vao);
    glBindVertexArray(b.vao);
    glGenBuffers(1, &b.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
    const GLsizei stride = sizeof(Vertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, color)));
    if (indices) {
        glGenBuffers(1, &b.ebo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ebo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices->size() * sizeof(uint32_t)), indices->data(),
                     GL_STATIC_DRAW);
        b.count = GLsizei(indices->size());
    } else {
        b.count = GLsizei(vertices.size());
    }
    glBindVertexArray(0);
    return b;
}

void check_count(size_t n, const char* what) {
    if (n > size_t(1) << 30) throw InvalidArgument(std::string(what) + ": too many to draw (over 2^30)");
}

/// @brief Throws InvalidArgument naming the first item (triangle, line) with an index outside [0, count).
template <int N>
void check_indices(const std::vector<Eigen::Matrix<int, N, 1>>& items, size_t count, const char* item,
                   const char* targets) {
    for (size_t i = 0; i < items.size(); ++i)
        for (int k = 0; k < N; ++k)
            if (items[i][k] < 0 || size_t(items[i][k]) >= count)
                throw InvalidArgument(std::string(item) + " " + std::to_string(i) + " has index " +
                                      std::to_string(items[i][k]) + ", out of range for " + std::to_string(count) +
                                      " " + targets);
}

Eigen::Vector3d face_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double len = n.norm();
    return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

/// @brief Flat-shaded triangles: three vertices of their own per triangle, with the face's normal.
void append_flat_triangle(std::vector<Vertex>& out, const Eigen::Vector3d* p, const Eigen::Vector3d* c) {
    const Eigen::Vector3d n = face_normal(p[0], p[1], p[2]);
    for (int k = 0; k < 3; ++k) out.push_back(vertex(p[k], n, c[k]));
}

/// @brief The vertices reordered along a Z-order curve over a 64^3 grid of `box` (a counting sort: linear time).
/// Nearby points then follow each other, so a software rasterizer (llvmpipe) bins and shades them tile by
/// tile with its caches warm: an unordered 1M-point cloud (e.g. after voxel down-sampling) draws about twice
/// as fast. Only points at exactly the same depth on the same pixel can show differently (the first drawn wins).
void order_spatially(std::vector<Vertex>& vertices, const SceneBox& box) {
    constexpr int kBits = 6, kCells = 1 << kBits;
    if (vertices.size() < 4096 || box.empty()) return;  // small clouds gain nothing
    const Eigen::Array3d low = box.min_bound.array();
    const double scale = kCells / box.max_extent();
    auto spread = [](uint32_t v) {  // abcdef -> a00b00c00d00e00f
        uint32_t out = 0;
        for (int bit = 0; bit < kBits; ++bit) out |= ((v >> bit) & 1u) << (3 * bit);
        return out;
    };
    uint32_t spread_of[kCells];
    for (int i = 0; i < kCells; ++i) spread_of[i] = spread(uint32_t(i));
    std::vector<uint32_t> keys(vertices.size());
    std::vector<uint32_t> start(size_t(1) << (3 * kBits), 0);
    for (size_t i = 0; i < vertices.size(); ++i) {
        uint32_t key = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const int cell = std::clamp(int((vertices[i].position[axis] - low[axis]) * scale), 0, kCells - 1);
            key |= spread_of[cell] << axis;
        }
        keys[i] = key;
        ++start[key];
    }
    uint32_t offset = 0;
    for (uint32_t& n : start) offset += std::exchange(n, offset);
    std::vector<Vertex> ordered(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) ordered[start[keys[i]]++] = vertices[i];
    vertices.swap(ordered);
}

}  // namespace

void VertexBuffer::release() {
    if (ebo) glDeleteBuffers(1, &ebo);
    if (vbo) glDeleteBuffers(1, &vbo);
    if (vao) glDeleteVertexArrays(1, &vao);
    *this = VertexBuffer();
}

void GpuGeometry::release() {
    if (texture) glDeleteTextures(1, &texture);
    texture = 0;
    main.release();
    smooth.release();
    normal_lines.release();
}

GpuGeometry upload(const geometry::PointCloud& cloud, const Material& material) {
    check_count(2 * cloud.size(), "points");
    GpuGeometry g;
    g.kind = GeometryKind::PointCloud;
    g.material = material;
    g.has_normals = cloud.has_normals();
    g.has_colors = cloud.has_colors();
    std::vector<Vertex> vertices;
    vertices.reserve(cloud.size());
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < cloud.size(); ++i) {
        if (!cloud.points[i].allFinite()) continue;  // not drawn, and not in the box
        g.box.add(cloud.points[i]);
        vertices.push_back(vertex(cloud.points[i], g.has_normals ? cloud.normals[i] : zero,
                                  g.has_colors ? cloud.colors[i] : zero));
    }
    order_spatially(vertices, g.box);
    g.main = make_buffer(vertices);
    if (g.has_normals) {
        std::vector<Vertex> doubled;
        doubled.reserve(2 * vertices.size());
        for (const Vertex& v : vertices) {
            doubled.push_back(v);
            doubled.push_back(v);
        }
        g.normal_lines = make_buffer(doubled);
    }
    return g;
}

GpuGeometry upload(const geometry::TriangleMesh& mesh, const Material& material) {
    const size_t nv = mesh.vertices.size();
    check_indices(mesh.triangles, nv, "triangle", "vertices");
    check_count(3 * mesh.triangles.size(), "triangles");
    GpuGeometry g;
    g.kind = GeometryKind::TriangleMesh;
    g.material = material;
    g.has_normals = true;  // flat shading always has face normals
    g.has_colors = mesh.has_vertex_colors();
    for (const Eigen::Vector3d& v : mesh.vertices) g.box.add(v);
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    std::vector<Vertex> flat;
    flat.reserve(3 * mesh.triangles.size());
    for (const Eigen::Vector3i& t : mesh.triangles) {
        const Eigen::Vector3d p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
        if (!p[0].allFinite() || !p[1].allFinite() || !p[2].allFinite()) continue;
        const Eigen::Vector3d c[3] = {g.has_colors ? mesh.vertex_colors[t[0]] : zero,
                                      g.has_colors ? mesh.vertex_colors[t[1]] : zero,
                                      g.has_colors ? mesh.vertex_colors[t[2]] : zero};
        append_flat_triangle(flat, p, c);
    }
    g.main = make_buffer(flat);
    if (mesh.has_vertex_normals()) {
        std::vector<Vertex> shared;
        shared.reserve(nv);
        for (size_t i = 0; i < nv; ++i)
            shared.push_back(vertex(mesh.vertices[i], mesh.vertex_normals[i], g.has_colors ? mesh.vertex_colors[i] : zero));
        std::vector<uint32_t> indices;
        indices.reserve(3 * mesh.triangles.size());
        for (const Eigen::Vector3i& t : mesh.triangles) {
            if (!mesh.vertices[t[0]].allFinite() || !mesh.vertices[t[1]].allFinite() || !mesh.vertices[t[2]].allFinite())
                continue;
            for (int k = 0; k < 3; ++k) indices.push_back(uint32_t(t[k]));
        }
        g.smooth = make_buffer(shared, &indices);
    }
    return g;
}

GpuGeometry upload(const geometry::LineSet& lines, const Material& material) {
    check_indices(lines.lines, lines.points.size(), "line", "points");
    check_count(2 * lines.lines.size(), "lines");
    GpuGeometry g;
    g.kind = GeometryKind::LineSet;
    g.material = material;
    g.has_colors = !lines.lines.empty() && lines.colors.size() == lines.lines.size();
    for (const Eigen::Vector3d& p : lines.points) g.box.add(p);
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    std::vector<Vertex> vertices;
    vertices.reserve(2 * lines.lines.size());
    for (size_t l = 0; l < lines.lines.size(); ++l) {
        const Eigen::Vector3d& a = lines.points[lines.lines[l][0]];
        const Eigen::Vector3d& b = lines.points[lines.lines[l][1]];
        if (!a.allFinite() || !b.allFinite()) continue;
        const Eigen::Vector3d c = g.has_colors ? lines.colors[l] : zero;  // Open3D: black without colors
        vertices.push_back(vertex(a, zero, c));
        vertices.push_back(vertex(b, zero, c));
    }
    g.main = make_buffer(vertices);
    return g;
}

GpuGeometry upload(const geometry::VoxelGrid& grid, const Material& material) {
    check_count(36 * grid.voxels.size(), "voxels");
    GpuGeometry g;
    g.kind = GeometryKind::VoxelGrid;
    g.material = material;
    g.has_normals = true;
    for (const geometry::Voxel& v : grid.voxels) g.has_colors = g.has_colors || !v.color.isZero();
    // The 12 triangles of a unit cube, counter-clockwise seen from outside; corner k is (k&1, k&2, k&4).
    static const int kCube[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                     {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    std::vector<Vertex> vertices;
    vertices.reserve(36 * grid.voxels.size());
    for (const geometry::Voxel& v : grid.voxels) {
        const Eigen::Vector3d base = grid.origin + grid.voxel_size * v.grid_index.cast<double>();
        Eigen::Vector3d corner[8];
        for (int k = 0; k < 8; ++k)
            corner[k] = base + grid.voxel_size * Eigen::Vector3d((k & 1) ? 1 : 0, (k & 2) ? 1 : 0, (k & 4) ? 1 : 0);
        g.box.add(corner[0]);
        g.box.add(corner[7]);
        const Eigen::Vector3d c[3] = {v.color, v.color, v.color};
        for (const auto& t : kCube) {
            const Eigen::Vector3d p[3] = {corner[t[0]], corner[t[1]], corner[t[2]]};
            append_flat_triangle(vertices, p, c);
        }
    }
    g.main = make_buffer(vertices);
    return g;
}

namespace {

/// @brief The image as tightly packed RGB8 (see upload's formats); throws InvalidArgument for others.
std::vector<uint8_t> to_rgb8(const geometry::Image& image) {
    const int c = image.num_channels, b = image.bytes_per_channel;
    const bool ok = (b == 1 && (c == 1 || c == 3 || c == 4)) || (b == 2 && c == 1) || (b == 4 && (c == 1 || c == 3));
    if (image.empty() || !ok || image.data.size() != image.byte_size())
        throw InvalidArgument("an image to show needs pixels: 1, 3 or 4 channels of uint8, 1 of uint16, or 1 or 3 of "
                              "float32");
    const size_t n = size_t(image.width) * size_t(image.height);
    std::vector<uint8_t> rgb(3 * n);
    auto value = [&](size_t i, int k) -> double {
        const uint8_t* p = image.data.data() + (i * c + k) * b;
        if (b == 1) return *p / 255.0;
        if (b == 2) {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        float v;
        std::memcpy(&v, p, 4);
        return std::isfinite(v) ? v : 0.0;
    };
    double scale = 1.0;  // one channel of depth-like values: gray up to the largest
    if (c == 1 && b != 1) {
        double top = 0;
        for (size_t i = 0; i < n; ++i) top = std::max(top, value(i, 0));
        scale = top > 0 ? 1.0 / top : 1.0;
    }
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            const double v = value(i, c == 1 ? 0 : k) * scale;
            rgb[3 * i + k] = uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
        }
    return rgb;
}

}  // namespace

GpuGeometry upload(const geometry::Image& image, int width, int height) {
    const std::vector<uint8_t> rgb = to_rgb8(image);
    GpuGeometry g;
    g.kind = GeometryKind::Image;
    g.material.shader = Shader::DefaultUnlit;
    // The quad's corners in normalized device coordinates, and texture coordinates in the color slot.
    const double scale = std::min(double(width) / image.width, double(height) / image.height);
    const float sx = float(image.width * scale / width), sy = float(image.height * scale / height);
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    auto corner = [&](float x, float y, float u, float v) {
        return vertex(Eigen::Vector3d(x * sx, y * sy, 0), zero, Eigen::Vector3d(u, v, 0));
    };
    // Texture row 0 is the image's top row, drawn at the quad's top (y = +1).
    const std::vector<Vertex> quad = {corner(-1, -1, 0, 1), corner(1, -1, 1, 1), corner(1, 1, 1, 0),
                                      corner(-1, -1, 0, 1), corner(1, 1, 1, 0), corner(-1, 1, 0, 0)};
    g.main = make_buffer(quad);
    glGenTextures(1, &g.texture);
    glBindTexture(GL_TEXTURE_2D, g.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // enlarged pixels stay sharp
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return g;
}

GpuGeometry upload_outline(const std::vector<Eigen::Vector2d>& pixels, int width, int height) {
    GpuGeometry g;
    g.kind = GeometryKind::LineSet;
    g.material.shader = Shader::DefaultUnlit;
    std::vector<Vertex> vertices;
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    for (const Eigen::Vector2d& p : pixels)  // pixel centres, as gl_projection maps them
        vertices.push_back(vertex(Eigen::Vector3d(2.0 * (p.x() + 0.5) / width - 1.0, 1.0 - 2.0 * (p.y() + 0.5) / height, 0),
                                  zero, zero));
    g.main = make_buffer(vertices);
    return g;
}

}  // namespace o3d::visualization
