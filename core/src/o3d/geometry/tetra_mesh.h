// SPDX-License-Identifier: MIT
#pragma once
/// @file tetra_mesh.h
/// @brief The tetrahedral-mesh container, the 3-D Delaunay tetrahedralization of a point set (Qhull) and
/// iso-surface extraction by marching tetrahedra (Open3D's TetraMesh, CreateFromPointCloud,
/// ExtractTriangleMesh).
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Vertices and tetrahedra (four vertex indices each). Tetra indices are not trusted: algorithms
/// check them (validate_tetras) before following them.
struct TetraMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector4i> tetras;

    bool has_vertices() const { return !vertices.empty(); }
    bool has_tetras() const { return !vertices.empty() && !tetras.empty(); }
    void clear() { *this = TetraMesh(); }
};

/// @brief A tetrahedralization plus, for each of its vertices, the input point it is.
struct TetraMeshFromPoints {
    TetraMesh mesh;
    std::vector<size_t> point_map;  ///< point_map[v] = input index of vertex v
};

/// @brief Delaunay tetrahedralization of `points` (Qhull "d Qbb Qt Qz Q5" on the points centred on their
/// bounding box). Vertices are the input points Qhull used, in ascending input order (point_map is
/// increasing; of exact duplicates Qhull keeps one copy); every tetrahedron is positively oriented
/// (det[b-a, c-a, d-a] >= 0). Sets with cospherical subsets (grids, cube corners) are triangulated; such
/// a set may yield zero-volume tetrahedra, as in Open3D.
/// @throws InvalidArgument on < 4 points, non-finite points, more than 2^31 - 1 points, or a degenerate
///   (coplanar / collinear / coincident) set — a clear error carrying Qhull's reason, never an abort.
TetraMeshFromPoints create_tetra_mesh_from_points(const std::vector<Eigen::Vector3d>& points);

/// @brief Open3D's TetraMesh::ExtractTriangleMesh: the iso-surface of per-vertex `values` at `level` by
/// marching tetrahedra. A surface vertex lies on each tetra edge whose ends fall on different sides
/// (value < level against value >= level), linearly interpolated, and is shared by every tetrahedron of
/// that edge; a tetrahedron gives one triangle (one corner apart) or two (two and two). Triangles are
/// wound so that their normals point toward increasing values (as Open3D). Vertices are numbered in
/// ascending order of their edge (smaller vertex index, then larger); triangles follow the tetra order.
/// @throws InvalidArgument on values.size() != vertices.size(), a non-finite value or level, or a tetra
///   index out of range.
TriangleMesh extract_triangle_mesh(const TetraMesh& tetra_mesh, const std::vector<double>& values, double level);

}  // namespace o3d::geometry
