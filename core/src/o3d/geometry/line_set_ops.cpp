// SPDX-License-Identifier: MIT
#include "o3d/geometry/line_set_ops.h"

#include <string>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

bool in_range(int i, size_t n) { return i >= 0 && static_cast<size_t>(i) < n; }

/// Corner k of a box as signs along its three axes, in Open3D's get_box_points order.
constexpr int kCornerSigns[8][3] = {{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1},
                                    {1, 1, 1},    {-1, 1, 1},  {1, -1, 1},  {1, 1, -1}};
/// The 12 box edges on those corners, as Open3D lists them: bottom ring, top ring, then the uprights.
constexpr int kBoxEdges[12][2] = {{0, 1}, {1, 7}, {7, 2}, {2, 0}, {3, 6}, {6, 4},
                                  {4, 5}, {5, 3}, {0, 3}, {1, 6}, {7, 4}, {2, 5}};

}  // namespace

void validate_lines(const LineSet& lines) {
    const size_t n = lines.points.size();
    for (size_t i = 0; i < lines.lines.size(); ++i) {
        const Eigen::Vector2i& l = lines.lines[i];
        if (!in_range(l(0), n) || !in_range(l(1), n))
            throw o3d::InvalidArgument("line " + std::to_string(i) + " = (" + std::to_string(l(0)) + ", " +
                                       std::to_string(l(1)) + ") indexes outside the " + std::to_string(n) +
                                       " points");
    }
}

void transform_line_set(LineSet& lines, const Eigen::Matrix4d& transform) {
    if (!transform.allFinite()) throw o3d::InvalidArgument("transformation has a non-finite entry");
    for (Eigen::Vector3d& p : lines.points) {
        const Eigen::Vector4d h = transform * p.homogeneous();
        p = h.head<3>() / h(3);
    }
}

void paint_line_set(LineSet& lines, const Eigen::Vector3d& rgb) {
    if (!rgb.allFinite()) throw o3d::InvalidArgument("color has a non-finite entry");
    lines.colors.assign(lines.lines.size(), rgb.cwiseMax(0.0).cwiseMin(1.0));
}

LineSet line_set_from_correspondences(const PointCloud& cloud0, const PointCloud& cloud1,
                                      const std::vector<Eigen::Vector2i>& pairs) {
    const size_t n0 = cloud0.points.size(), n1 = cloud1.points.size();
    if (n0 + n1 > static_cast<size_t>(INT32_MAX)) throw o3d::InvalidArgument("the clouds hold too many points");
    LineSet out;
    out.points.reserve(n0 + n1);
    out.points.insert(out.points.end(), cloud0.points.begin(), cloud0.points.end());
    out.points.insert(out.points.end(), cloud1.points.begin(), cloud1.points.end());
    out.lines.reserve(pairs.size());
    for (size_t i = 0; i < pairs.size(); ++i) {
        const Eigen::Vector2i& p = pairs[i];
        if (!in_range(p(0), n0) || !in_range(p(1), n1))
            throw o3d::InvalidArgument("correspondence " + std::to_string(i) + " = (" + std::to_string(p(0)) + ", " +
                                       std::to_string(p(1)) + ") is outside the clouds (" + std::to_string(n0) +
                                       " and " + std::to_string(n1) + " points)");
        out.lines.emplace_back(p(0), static_cast<int>(n0) + p(1));
    }
    return out;
}

std::array<Eigen::Vector3d, 8> oriented_box_corners(const Eigen::Vector3d& center, const Eigen::Matrix3d& R,
                                                    const Eigen::Vector3d& extent) {
    const Eigen::Vector3d half = extent / 2.0;
    std::array<Eigen::Vector3d, 8> corners;
    for (int k = 0; k < 8; ++k) {
        Eigen::Vector3d p = center;
        for (int axis = 0; axis < 3; ++axis) p += kCornerSigns[k][axis] * half(axis) * R.col(axis);
        corners[k] = p;
    }
    return corners;
}

LineSet line_set_from_oriented_box(const Eigen::Vector3d& center, const Eigen::Matrix3d& R,
                                   const Eigen::Vector3d& extent) {
    const std::array<Eigen::Vector3d, 8> corners = oriented_box_corners(center, R, extent);
    LineSet out;
    out.points.assign(corners.begin(), corners.end());
    for (const auto& e : kBoxEdges) out.lines.emplace_back(e[0], e[1]);
    return out;
}

LineSet line_set_from_axis_aligned_box(const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound) {
    return line_set_from_oriented_box((min_bound + max_bound) / 2.0, Eigen::Matrix3d::Identity(),
                                      max_bound - min_bound);
}

LineSet line_set_from_triangle_mesh(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    const MeshEdges edges = mesh_edges(mesh);
    LineSet out;
    out.points = mesh.vertices;
    out.lines.reserve(edges.size());
    // Edges are numbered by first appearance, so a side whose edge number is the next one is where
    // that edge first appears: keep the side's own orientation, as Open3D does.
    for (size_t s = 0; s < edges.side_edge.size(); ++s) {
        if (static_cast<size_t>(edges.side_edge[s]) != out.lines.size()) continue;
        const Eigen::Vector3i& tri = mesh.triangles[s / 3];
        const int k = static_cast<int>(s % 3);
        out.lines.emplace_back(tri(k), tri((k + 1) % 3));
    }
    return out;
}

}  // namespace o3d::geometry
