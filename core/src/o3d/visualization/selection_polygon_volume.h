// SPDX-License-Identifier: MIT
#pragma once
/// @file selection_polygon_volume.h
/// @brief Open3D's SelectionPolygonVolume: a prism whose cross-section is a polygon in the plane of two axes
/// and whose extent along the third (the orthogonal axis) is [axis_min, axis_max]. Cropping keeps what lies
/// inside. Its JSON is the file VisualizerWithEditing writes next to a crop (class_name
/// "SelectionPolygonVolume"), so Open3D's files read here and ours read there.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::visualization {

struct SelectionPolygonVolume {
    int orthogonal_axis = 1;  ///< 0, 1, 2 for X, Y, Z (Open3D's "X" / "Y" / "Z")
    double axis_min = 0.0, axis_max = 0.0;
    /// Corners in order; the coordinate along the orthogonal axis is ignored.
    std::vector<Eigen::Vector3d> bounding_polygon;
};

/// @brief Throws InvalidArgument unless the axis is 0..2, the range finite with min <= max, and the polygon
/// has at least 3 finite corners.
void check_volume(const SelectionPolygonVolume& volume);

/// @brief Whether (x, y) lies inside the closed polygon (even-odd rule; a point on an edge may go either way).
bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, double x, double y);

/// @brief Indices of the points inside the volume, ascending (Open3D's crop_in_polygon).
std::vector<int64_t> crop_in_polygon(const SelectionPolygonVolume& volume, const std::vector<Eigen::Vector3d>& points);
/// @brief The points inside, with their normals, colors and covariances.
geometry::PointCloud crop_point_cloud(const SelectionPolygonVolume& volume, const geometry::PointCloud& cloud);
/// @brief The triangles whose three vertices are inside, with the vertices they use (mesh_crop's rule).
geometry::TriangleMesh crop_triangle_mesh(const SelectionPolygonVolume& volume, const geometry::TriangleMesh& mesh);

/// @brief Parse Open3D's JSON; throws ParseError naming what is wrong.
SelectionPolygonVolume selection_polygon_volume_from_json(const std::string& text);
std::string selection_polygon_volume_to_json(const SelectionPolygonVolume& volume);

}  // namespace o3d::visualization
