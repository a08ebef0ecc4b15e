// SPDX-License-Identifier: MIT
#pragma once
/// @file triangle_mesh.h
/// @brief The triangle-mesh container: contiguous arrays (zero-copy views are legal).
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/image.h"

namespace o3d::geometry {

/// @brief Vertices with optional per-vertex normals and colors; triangles (vertex indices) with optional
/// per-triangle normals, three UVs per triangle and a material id per triangle; texture images.
/// Attributes count only when their size matches (Open3D semantics). Triangle indices are not trusted:
/// algorithms check them (validate_triangles) before following them.
struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3d> vertex_normals;
    std::vector<Eigen::Vector3d> vertex_colors;
    std::vector<Eigen::Vector3i> triangles;
    std::vector<Eigen::Vector3d> triangle_normals;
    std::vector<Eigen::Vector2d> triangle_uvs;  ///< 3 per triangle, in corner order
    std::vector<int> triangle_material_ids;
    std::vector<Image> textures;

    bool has_vertices() const { return !vertices.empty(); }
    bool has_triangles() const { return !vertices.empty() && !triangles.empty(); }
    bool has_vertex_normals() const { return !vertices.empty() && vertex_normals.size() == vertices.size(); }
    bool has_vertex_colors() const { return !vertices.empty() && vertex_colors.size() == vertices.size(); }
    bool has_triangle_normals() const { return has_triangles() && triangle_normals.size() == triangles.size(); }
    bool has_triangle_uvs() const { return has_triangles() && triangle_uvs.size() == 3 * triangles.size(); }
    bool has_triangle_material_ids() const {
        return has_triangles() && triangle_material_ids.size() == triangles.size();
    }
    bool has_textures() const { return !textures.empty(); }
    void clear() { *this = TriangleMesh(); }
};

}  // namespace o3d::geometry
