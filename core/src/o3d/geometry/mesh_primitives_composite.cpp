// SPDX-License-Identifier: MIT
// Primitives built from others (arrow, coordinate frame) and the regular solids, in Open3D 0.20's layout.
#include <Eigen/Geometry>
#include <cmath>

#include "o3d/geometry/mesh_primitives.h"
#include "o3d/geometry/mesh_primitives_checks.h"

namespace o3d::geometry {
namespace {

/// @brief Append `part` to `mesh`, moved by `rotation` then `offset`, its triangles re-indexed, its vertices
/// given `color` when one is passed.
void append(TriangleMesh& mesh, const TriangleMesh& part, const Eigen::Matrix3d& rotation,
            const Eigen::Vector3d& offset, const Eigen::Vector3d* color = nullptr) {
    const int base = static_cast<int>(mesh.vertices.size());
    for (const Eigen::Vector3d& v : part.vertices) mesh.vertices.push_back(rotation * v + offset);
    if (color) mesh.vertex_colors.insert(mesh.vertex_colors.end(), part.vertices.size(), *color);
    for (const Eigen::Vector3i& t : part.triangles) mesh.triangles.push_back(t + Eigen::Vector3i::Constant(base));
}

/// @brief Unit triangle normals, and unit vertex normals from the area-weighted sum of the triangles'
/// cross products (as Open3D's compute_vertex_normals gives them).
void add_normals(TriangleMesh& m) {
    m.triangle_normals.resize(m.triangles.size());
    m.vertex_normals.assign(m.vertices.size(), Eigen::Vector3d::Zero());
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = m.triangles[t];
        const Eigen::Vector3d& a = m.vertices[static_cast<size_t>(tri[0])];
        const Eigen::Vector3d c = (m.vertices[static_cast<size_t>(tri[1])] - a).cross(m.vertices[static_cast<size_t>(tri[2])] - a);
        for (int k = 0; k < 3; ++k) m.vertex_normals[static_cast<size_t>(tri[k])] += c;
        m.triangle_normals[t] = c;
    }
    for (auto* normals : {&m.triangle_normals, &m.vertex_normals})
        for (Eigen::Vector3d& n : *normals) {
            const double len = n.norm();
            if (len > 0) n /= len;
        }
}

TriangleMesh from_tables(double radius, const double (*vertices)[3], int nv, const int (*triangles)[3], int nt) {
    detail::require_positive(radius, "radius");
    TriangleMesh m;
    for (int i = 0; i < nv; ++i) m.vertices.emplace_back(Eigen::Vector3d(vertices[i][0], vertices[i][1], vertices[i][2]));
    const double scale = radius / m.vertices[0].norm();  // the tables' vertices all share one length
    for (Eigen::Vector3d& v : m.vertices) v *= scale;
    for (int t = 0; t < nt; ++t) m.triangles.emplace_back(triangles[t][0], triangles[t][1], triangles[t][2]);
    return m;
}

}  // namespace

TriangleMesh create_arrow(double cylinder_radius, double cone_radius, double cylinder_height, double cone_height,
                          int resolution, int cylinder_split, int cone_split) {
    detail::require_positive(cylinder_radius, "cylinder_radius");
    detail::require_positive(cone_radius, "cone_radius");
    detail::require_positive(cylinder_height, "cylinder_height");
    detail::require_positive(cone_height, "cone_height");
    detail::require_at_least(resolution, 1, "resolution");
    detail::require_at_least(cylinder_split, 1, "cylinder_split");
    detail::require_at_least(cone_split, 1, "cone_split");
    detail::require_indexable(4 + int64_t{resolution} * (int64_t{cylinder_split} + 1 + cone_split), "create_arrow");
    TriangleMesh m = create_cylinder(cylinder_radius, cylinder_height, resolution, cylinder_split);
    for (Eigen::Vector3d& v : m.vertices) v.z() += 0.5 * cylinder_height;
    append(m, create_cone(cone_radius, cone_height, resolution, cone_split), Eigen::Matrix3d::Identity(),
           Eigen::Vector3d(0, 0, cylinder_height));
    return m;
}

TriangleMesh create_coordinate_frame(double size, const Eigen::Vector3d& origin) {
    detail::require_positive(size, "size");
    if (!origin.allFinite()) throw InvalidArgument("origin must be finite");
    TriangleMesh m;
    const Eigen::Vector3d grey(0.5, 0.5, 0.5), red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
    append(m, create_sphere(0.06 * size, 20), Eigen::Matrix3d::Identity(), origin, &grey);
    const TriangleMesh arrow = create_arrow(0.035 * size, 0.06 * size, 0.8 * size, 0.2 * size, 20, 4, 1);
    // The arrow points along z; cyclic permutations of the axes turn it onto x and y.
    Eigen::Matrix3d to_x, to_y;
    to_x << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // (x, y, z) -> (z, x, y)
    to_y << 0, 1, 0, 0, 0, 1, 1, 0, 0;  // (x, y, z) -> (y, z, x)
    append(m, arrow, to_x, origin, &red);
    append(m, arrow, to_y, origin, &green);
    append(m, arrow, Eigen::Matrix3d::Identity(), origin, &blue);
    add_normals(m);
    return m;
}

TriangleMesh create_tetrahedron(double radius) {
    static const double kVertices[4][3] = {{std::sqrt(8.0 / 9.0), 0.0, -1.0 / 3.0},
                                           {-std::sqrt(2.0 / 9.0), std::sqrt(2.0 / 3.0), -1.0 / 3.0},
                                           {-std::sqrt(2.0 / 9.0), -std::sqrt(2.0 / 3.0), -1.0 / 3.0},
                                           {0.0, 0.0, 1.0}};
    static const int kTriangles[4][3] = {{0, 2, 1}, {0, 3, 2}, {0, 1, 3}, {1, 2, 3}};
    return from_tables(radius, kVertices, 4, kTriangles, 4);
}

TriangleMesh create_octahedron(double radius) {
    static const double kVertices[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    static const int kTriangles[8][3] = {{0, 1, 2}, {1, 3, 2}, {3, 4, 2}, {4, 0, 2},
                                         {0, 5, 1}, {1, 5, 3}, {3, 5, 4}, {4, 5, 0}};
    return from_tables(radius, kVertices, 6, kTriangles, 8);
}

TriangleMesh create_icosahedron(double radius) {
    const double p = (1.0 + std::sqrt(5.0)) / 2.0;  // the golden ratio
    const double kVertices[12][3] = {{-1, 0, p}, {1, 0, p},  {1, 0, -p},  {-1, 0, -p}, {0, -p, 1}, {0, p, 1},
                                     {0, p, -1}, {0, -p, -1}, {-p, -1, 0}, {p, -1, 0},  {p, 1, 0},  {-p, 1, 0}};
    static const int kTriangles[20][3] = {{0, 4, 1},  {0, 1, 5},  {1, 4, 9},  {1, 9, 10}, {1, 10, 5},
                                          {0, 8, 4},  {0, 11, 8}, {0, 5, 11}, {5, 6, 11}, {5, 10, 6},
                                          {4, 8, 7},  {4, 7, 9},  {3, 6, 2},  {3, 2, 7},  {2, 6, 10},
                                          {2, 10, 9}, {2, 9, 7},  {3, 11, 6}, {3, 8, 11}, {3, 7, 8}};
    return from_tables(radius, kVertices, 12, kTriangles, 20);
}

}  // namespace o3d::geometry
