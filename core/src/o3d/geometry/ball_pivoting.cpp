// SPDX-License-Identifier: MIT
#include "o3d/geometry/ball_pivoting.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/geometry/ball_pivoting_mesher.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

void validate(const PointCloud& cloud, const std::vector<double>& radii) {
    if (!cloud.has_points()) throw InvalidArgument("ball pivoting needs a non-empty cloud");
    if (!cloud.has_normals()) throw InvalidArgument("ball pivoting needs normals (call estimate_normals first)");
    if (cloud.size() > static_cast<size_t>(INT32_MAX))
        throw InvalidArgument("ball pivoting takes at most 2^31 - 1 points, got " + std::to_string(cloud.size()));
    for (size_t i = 0; i < cloud.size(); ++i) {
        if (!cloud.points[i].allFinite()) throw InvalidArgument("point " + std::to_string(i) + " is not finite");
        if (!cloud.normals[i].allFinite()) throw InvalidArgument("normal " + std::to_string(i) + " is not finite");
    }
    if (radii.empty()) throw InvalidArgument("ball pivoting needs at least one radius");
    for (size_t i = 0; i < radii.size(); ++i) {
        if (!std::isfinite(radii[i]) || !(radii[i] > 0.0))
            throw InvalidArgument("ball pivoting radius " + std::to_string(i) + " must be finite and > 0, got " +
                                  std::to_string(radii[i]));
        // A smaller ball cannot pass where a larger one was stopped, so a decreasing radius is a mistake.
        if (i > 0 && !(radii[i] > radii[i - 1]))
            throw InvalidArgument("ball pivoting radii must be strictly increasing, radius " + std::to_string(i) +
                                  " (" + std::to_string(radii[i]) + ") follows " + std::to_string(radii[i - 1]));
    }
}

}  // namespace

TriangleMesh create_from_point_cloud_ball_pivoting(const PointCloud& cloud, const std::vector<double>& radii,
                                                   const std::function<bool(double)>& progress) {
    validate(cloud, radii);
    ball_pivoting::Mesher mesher(cloud.points, cloud.normals, progress);
    mesher.run(radii);

    TriangleMesh mesh;
    mesh.vertices = cloud.points;
    mesh.vertex_normals = cloud.normals;
    if (cloud.has_colors()) mesh.vertex_colors = cloud.colors;
    mesh.triangles = mesher.front().triangles();
    mesh.triangle_normals.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d d =
            (mesh.vertices[t(1)] - mesh.vertices[t(0)]).cross(mesh.vertices[t(2)] - mesh.vertices[t(0)]);
        mesh.triangle_normals.push_back(d.normalized());
    }
    return mesh;
}

}  // namespace o3d::geometry
