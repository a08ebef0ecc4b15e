// SPDX-License-Identifier: MIT
#include "o3d/geometry/oriented_bounding_box.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "o3d/geometry/convex_hull.h"
#include "o3d/geometry/mesh_crop.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

void require_nonzero_volume(const OrientedBoundingBox& box) {
    if (!(box.extent.minCoeff() > 0.0))
        throw InvalidArgument("the oriented box has zero size on an axis (Open3D: \"zeros size\")");
}

}  // namespace

OrientedBoundingBox obb_from_points(const std::vector<Eigen::Vector3d>& points, bool robust) {
    const ConvexHull hull = compute_convex_hull(points, robust);
    const std::vector<Eigen::Vector3d>& hp = hull.mesh.vertices;
    // Two-pass covariance of the hull's vertices (divided by N, as ComputeMeanAndCovariance).
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : hp) mean += p;
    mean /= static_cast<double>(hp.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : hp) cov.noalias() += (p - mean) * (p - mean).transpose();
    cov /= static_cast<double>(hp.size());

    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
    // Eigen sorts ascending; Open3D's box lists the axes by decreasing variance.
    Eigen::Matrix3d R;
    R.col(0) = solver.eigenvectors().col(2).normalized();
    R.col(1) = solver.eigenvectors().col(1).normalized();
    R.col(2) = R.col(0).cross(R.col(1));  // right-handed, so R is a rotation

    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
    for (const auto& p : hp) {
        const Eigen::Vector3d local = R.transpose() * (p - mean);
        lo = lo.cwiseMin(local);
        hi = hi.cwiseMax(local);
    }
    OrientedBoundingBox box;
    box.R = R;
    box.center = R * (0.5 * (lo + hi)) + mean;
    box.extent = hi - lo;
    return box;
}

OrientedBoundingBox obb_from_aabb(const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound) {
    if (!min_bound.allFinite() || !max_bound.allFinite()) throw InvalidArgument("box bounds must be finite");
    if ((max_bound - min_bound).minCoeff() < 0.0) throw InvalidArgument("max_bound < min_bound on an axis");
    OrientedBoundingBox box;
    box.center = 0.5 * (min_bound + max_bound);
    box.extent = max_bound - min_bound;
    return box;
}

std::array<Eigen::Vector3d, 8> box_points(const OrientedBoundingBox& box) {
    const Eigen::Vector3d x = box.R.col(0) * (0.5 * box.extent(0));
    const Eigen::Vector3d y = box.R.col(1) * (0.5 * box.extent(1));
    const Eigen::Vector3d z = box.R.col(2) * (0.5 * box.extent(2));
    const Eigen::Vector3d& c = box.center;
    return {c - x - y - z, c + x - y - z, c - x + y - z, c - x - y + z,
            c + x + y + z, c - x + y + z, c + x - y + z, c + x + y - z};
}

void validate_obb(const OrientedBoundingBox& box) {
    if (!box.center.allFinite() || !box.R.allFinite() || !box.extent.allFinite())
        throw InvalidArgument("the oriented box has a non-finite entry");
    if (box.extent.minCoeff() < 0.0) throw InvalidArgument("the oriented box has a negative extent");
    if (!(box.R.transpose() * box.R).isApprox(Eigen::Matrix3d::Identity(), 1e-6))
        throw InvalidArgument("the oriented box's R is not orthonormal");
}

std::vector<int64_t> indices_in_obb(const std::vector<Eigen::Vector3d>& points, const OrientedBoundingBox& box) {
    validate_obb(box);
    // A few ulps of slack at the scale of the box and its position: the box of a set must contain the
    // set's own extreme points, which R^T (p - c) rounds to either side of the face.
    const double slack = 16.0 * std::numeric_limits<double>::epsilon() *
                         (box.extent.maxCoeff() + box.center.cwiseAbs().maxCoeff());
    const Eigen::Vector3d half = (0.5 * box.extent).array() + slack;
    const Eigen::Matrix3d Rt = box.R.transpose();
    std::vector<int64_t> indices;
    for (size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d local = Rt * (points[i] - box.center);
        // Written as <= so that NaN compares false and stays outside.
        if (std::abs(local(0)) <= half(0) && std::abs(local(1)) <= half(1) && std::abs(local(2)) <= half(2))
            indices.push_back(static_cast<int64_t>(i));
    }
    return indices;
}

PointCloud crop_obb(const PointCloud& cloud, const OrientedBoundingBox& box, bool invert) {
    validate_obb(box);
    require_nonzero_volume(box);
    return select_by_index(cloud, indices_in_obb(cloud.points, box), invert);
}

TriangleMesh crop_obb(const TriangleMesh& mesh, const OrientedBoundingBox& box) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    validate_obb(box);
    require_nonzero_volume(box);
    std::vector<uint8_t> inside(mesh.vertices.size(), 0);
    for (int64_t v : indices_in_obb(mesh.vertices, box)) inside[static_cast<size_t>(v)] = 1;

    return keep_triangles_inside(mesh, inside);
}

}  // namespace o3d::geometry
