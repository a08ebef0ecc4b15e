// SPDX-License-Identifier: MIT
#include "o3d/visualization/selection_polygon_volume.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "o3d/geometry/mesh_crop.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

/// @brief The two axes spanning the polygon's plane: (Y, Z) for X, (X, Z) for Y, (X, Y) for Z, as Open3D.
std::pair<int, int> plane_axes(int orthogonal_axis) {
    return orthogonal_axis == 0 ? std::make_pair(1, 2) : orthogonal_axis == 1 ? std::make_pair(0, 2) : std::make_pair(0, 1);
}

/// @brief Per point: inside the volume or not.
std::vector<uint8_t> inside_mask(const SelectionPolygonVolume& volume, const std::vector<Eigen::Vector3d>& points) {
    check_volume(volume);
    const auto [u, v] = plane_axes(volume.orthogonal_axis);
    std::vector<Eigen::Vector2d> polygon;
    for (const Eigen::Vector3d& corner : volume.bounding_polygon) polygon.emplace_back(corner[u], corner[v]);
    std::vector<uint8_t> inside(points.size(), 0);
    for (size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d& p = points[i];
        const double along = p[volume.orthogonal_axis];
        // NaN compares false both ways, so a non-finite point is never inside.
        if (!(along >= volume.axis_min && along <= volume.axis_max)) continue;
        inside[i] = inside_polygon(polygon, p[u], p[v]);
    }
    return inside;
}

}  // namespace

void check_volume(const SelectionPolygonVolume& volume) {
    if (volume.orthogonal_axis < 0 || volume.orthogonal_axis > 2)
        throw InvalidArgument("orthogonal_axis must be X, Y or Z");
    if (!std::isfinite(volume.axis_min) || !std::isfinite(volume.axis_max) || volume.axis_min > volume.axis_max)
        throw InvalidArgument("axis_min and axis_max must be finite with axis_min <= axis_max");
    if (volume.bounding_polygon.size() < 3)
        throw InvalidArgument("bounding_polygon needs at least 3 corners, got " +
                              std::to_string(volume.bounding_polygon.size()));
    for (const Eigen::Vector3d& corner : volume.bounding_polygon)
        if (!corner.allFinite()) throw InvalidArgument("bounding_polygon has a non-finite corner");
}

bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, double x, double y) {
    // Even-odd rule: count the edges a ray from (x, y) towards +x crosses.
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[j];
        if ((a.y() > y) == (b.y() > y)) continue;  // the edge does not straddle the ray's line
        const double crossing_x = a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
        if (x < crossing_x) inside = !inside;
    }
    return inside;
}

std::vector<int64_t> crop_in_polygon(const SelectionPolygonVolume& volume, const std::vector<Eigen::Vector3d>& points) {
    const std::vector<uint8_t> inside = inside_mask(volume, points);
    std::vector<int64_t> indices;
    for (size_t i = 0; i < inside.size(); ++i)
        if (inside[i]) indices.push_back(int64_t(i));
    return indices;
}

geometry::PointCloud crop_point_cloud(const SelectionPolygonVolume& volume, const geometry::PointCloud& cloud) {
    return geometry::select_by_mask(cloud, inside_mask(volume, cloud.points));
}

geometry::TriangleMesh crop_triangle_mesh(const SelectionPolygonVolume& volume, const geometry::TriangleMesh& mesh) {
    geometry::validate_triangles(mesh);
    return geometry::keep_triangles_inside(mesh, inside_mask(volume, mesh.vertices));
}

SelectionPolygonVolume selection_polygon_volume_from_json(const std::string& text) {
    using nlohmann::json;
    SelectionPolygonVolume volume;
    try {
        const json j = json::parse(text);
        if (!j.is_object() || j.value("class_name", std::string()) != "SelectionPolygonVolume")
            throw ParseError("not a SelectionPolygonVolume (\"class_name\" must be \"SelectionPolygonVolume\")");
        const std::string axis = j.at("orthogonal_axis").get<std::string>();
        if (axis != "X" && axis != "Y" && axis != "Z" && axis != "x" && axis != "y" && axis != "z")
            throw ParseError("SelectionPolygonVolume: \"orthogonal_axis\" must be \"X\", \"Y\" or \"Z\", got \"" + axis + "\"");
        volume.orthogonal_axis = (axis[0] | 0x20) - 'x';
        volume.axis_min = j.at("axis_min").get<double>();
        volume.axis_max = j.at("axis_max").get<double>();
        for (const json& corner : j.at("bounding_polygon")) {
            if (!corner.is_array() || corner.size() != 3)
                throw ParseError("SelectionPolygonVolume: each \"bounding_polygon\" corner must be 3 numbers");
            volume.bounding_polygon.emplace_back(corner[0].get<double>(), corner[1].get<double>(), corner[2].get<double>());
        }
    } catch (const json::exception& e) {
        throw ParseError(std::string("SelectionPolygonVolume JSON: ") + e.what());
    }
    try {
        check_volume(volume);
    } catch (const InvalidArgument& e) {
        throw ParseError(std::string("SelectionPolygonVolume: ") + e.what());
    }
    return volume;
}

std::string selection_polygon_volume_to_json(const SelectionPolygonVolume& volume) {
    check_volume(volume);
    nlohmann::json polygon = nlohmann::json::array();
    for (const Eigen::Vector3d& c : volume.bounding_polygon) polygon.push_back({c.x(), c.y(), c.z()});
    const nlohmann::json j = {{"class_name", "SelectionPolygonVolume"},
                              {"version_major", 1},
                              {"version_minor", 0},
                              {"orthogonal_axis", std::string(1, char('X' + volume.orthogonal_axis))},
                              {"axis_min", volume.axis_min},
                              {"axis_max", volume.axis_max},
                              {"bounding_polygon", polygon}};
    return j.dump(4);
}

}  // namespace o3d::visualization
