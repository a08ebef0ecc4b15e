// SPDX-License-Identifier: MIT
#include "o3d/geometry/hidden_point_removal.h"

#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {

ConvexHull hidden_point_removal(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& camera,
                                double radius) {
    if (!std::isfinite(radius) || radius <= 0.0)
        throw InvalidArgument("radius must be finite and > 0, got " + std::to_string(radius));
    if (!camera.allFinite()) throw InvalidArgument("camera_location has a non-finite entry");
    if (points.size() < 4)
        throw InvalidArgument("hidden point removal needs at least 4 points, got " + std::to_string(points.size()));

    // Flipped points live in camera coordinates, so the camera itself is the origin.
    std::vector<Eigen::Vector3d> flipped(points.size() + 1);
    for (size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) throw InvalidArgument("point " + std::to_string(i) + " is not finite");
        const Eigen::Vector3d d = points[i] - camera;
        const double norm = d.norm();
        if (norm == 0.0) throw InvalidArgument("point " + std::to_string(i) + " is at the camera location");
        flipped[i] = d + 2.0 * (radius - norm) * d / norm;
    }
    flipped.back() = Eigen::Vector3d::Zero();
    const int camera_id = static_cast<int>(points.size());

    ConvexHull hull = compute_convex_hull(flipped, false);
    // Renumber without the camera's vertex; drop the triangles that used it.
    ConvexHull visible;
    std::vector<int> renumber(hull.point_indices.size(), -1);
    for (size_t v = 0; v < hull.point_indices.size(); ++v) {
        const int pid = hull.point_indices[v];
        if (pid == camera_id) continue;
        renumber[v] = static_cast<int>(visible.point_indices.size());
        visible.point_indices.push_back(pid);
        visible.mesh.vertices.push_back(points[static_cast<size_t>(pid)]);
    }
    for (const Eigen::Vector3i& t : hull.mesh.triangles) {
        const Eigen::Vector3i r(renumber[t(0)], renumber[t(1)], renumber[t(2)]);
        if (r.minCoeff() >= 0) visible.mesh.triangles.push_back(r);
    }
    return visible;
}

}  // namespace o3d::geometry
