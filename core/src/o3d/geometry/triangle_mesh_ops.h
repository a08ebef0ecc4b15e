// SPDX-License-Identifier: MIT
#pragma once
/// @file triangle_mesh_ops.h
/// @brief Basic triangle-mesh operations with Open3D's semantics (o3d.geometry.TriangleMesh methods):
/// concatenation, normals, colors, rigid and affine transforms, bounds and surface area.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief `target += source` (Open3D operator+=): the source's triangles are re-indexed past the target's
/// vertices. A per-vertex or per-triangle attribute survives only when both meshes have it, or when the
/// target had no vertices (no triangles for per-triangle ones). Unlike Open3D, UVs, material ids (shifted
/// past the target's textures) and textures are concatenated too. An empty source changes nothing.
/// @throws InvalidArgument if either mesh has an out-of-range triangle index or the result would
/// need vertex indices beyond int32.
void append(TriangleMesh& target, const TriangleMesh& source);

/// @brief Component-wise min / max of the vertices; (0,0,0) when there are none.
Eigen::Vector3d min_bound(const TriangleMesh& mesh);
Eigen::Vector3d max_bound(const TriangleMesh& mesh);
/// @brief Mean of the vertices; (0,0,0) when there are none.
Eigen::Vector3d center(const TriangleMesh& mesh);

/// @brief v <- (T [v;1]) / w; vertex and triangle normals <- upper-left 3x3 of T times n.
void transform(TriangleMesh& mesh, const Eigen::Matrix4d& transformation);
/// @brief relative: v <- v + t; else the center moves to t.
void translate(TriangleMesh& mesh, const Eigen::Vector3d& translation, bool relative);
/// @brief v <- R (v - c) + c; vertex and triangle normals <- R n.
void rotate(TriangleMesh& mesh, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& center);
/// @brief v <- s (v - c) + c (normals unchanged, as Open3D).
void scale(TriangleMesh& mesh, double factor, const Eigen::Vector3d& center);

/// @brief Every vertex color set to `rgb`, clipped to [0,1] as Open3D does.
void paint_uniform_color(TriangleMesh& mesh, const Eigen::Vector3d& rgb);

/// @brief Triangle normals (b - a) x (c - a), scaled to unit length when `normalized` (a zero-area
/// triangle keeps (0,0,0)).
void compute_triangle_normals(TriangleMesh& mesh, bool normalized = true);
/// @brief Vertex normals as the sum of the (area-weighted, unnormalised) normals of the triangles around
/// each vertex, summed in triangle order; also sets the triangle normals, as Open3D. With `normalized`
/// both are scaled to unit length.
void compute_vertex_normals(TriangleMesh& mesh, bool normalized = true);
/// @brief Scale vertex and triangle normals to unit length (zero stays zero; NaN becomes (0,0,1), as Open3D).
void normalize_normals(TriangleMesh& mesh);

/// @brief Area of every triangle. @throws InvalidArgument on an out-of-range triangle index.
std::vector<double> triangle_areas(const TriangleMesh& mesh);
/// @brief Sum of the triangle areas, in triangle order (bitwise the same for any thread count).
double surface_area(const TriangleMesh& mesh);

}  // namespace o3d::geometry
