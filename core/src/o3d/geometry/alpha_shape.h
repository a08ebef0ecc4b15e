// SPDX-License-Identifier: MIT
#pragma once
/// @file alpha_shape.h
/// @brief Alpha shapes (Edelsbrunner & Muecke 1994) as Open3D builds them
/// (TriangleMesh::CreateFromPointCloudAlphaShape): the boundary of the union of the Delaunay tetrahedra
/// whose circumsphere radius is at most alpha.
#include <cstddef>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/tetra_mesh.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief The alpha shape's boundary triangles: the faces of the kept tetrahedra (circumradius <= alpha)
/// that are not shared by two kept tetrahedra, each wound so that its normal points out of its tetrahedron.
/// Zero-volume tetrahedra are never kept. The result is deterministic for any thread count.
///
/// When `tetra_mesh` (and `point_map`) are given — from create_tetra_mesh_from_points of the same cloud —
/// they are reused, as Open3D allows; `point_map` may be null only when the tetra mesh has one vertex per
/// cloud point (identity map). Output vertices: the tetra-mesh vertices some triangle uses, in tetra-mesh
/// order (ascending input order for a tetrahedralization of ours), with the cloud's normals and colors
/// (through point_map) when it has them — as Open3D, which also drops the unused vertices.
/// An alpha below every circumradius gives an empty mesh (Open3D warns and does the same). `num_threads`: 0 =
/// library default; the result does not depend on it.
/// @throws InvalidArgument on alpha <= 0 or non-finite, < 4 points, non-finite points, a coplanar /
///   collinear / coincident cloud (Open3D raises Qhull's error there too), tetra indices out of range, a
///   non-finite tetra vertex, or a point_map of the wrong size or with an index outside the cloud.
TriangleMesh create_from_point_cloud_alpha_shape(const PointCloud& cloud, double alpha,
                                                 const TetraMesh* tetra_mesh = nullptr,
                                                 const std::vector<size_t>* point_map = nullptr, int num_threads = 0);

}  // namespace o3d::geometry
