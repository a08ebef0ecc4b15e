// SPDX-License-Identifier: MIT
#pragma once
/// @file oriented_bounding_box.h
/// @brief Oriented bounding boxes (o3d.geometry.OrientedBoundingBox) and cropping by them.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Centre, rotation (column k = direction of extent k) and full edge lengths.
struct OrientedBoundingBox {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d extent = Eigen::Vector3d::Zero();

    double volume() const { return extent.prod(); }
};

/// @brief Open3D's OrientedBoundingBox::CreateFromPoints: PCA of the convex hull's vertices (axes by
/// decreasing variance, right-handed), then the tight axis-aligned box in that frame.
/// `robust` joggles the hull ("QJ") so flat sets still give a (flat) box.
/// @throws InvalidArgument as compute_convex_hull (fewer than 4 points, non-finite, coplanar without robust).
OrientedBoundingBox obb_from_points(const std::vector<Eigen::Vector3d>& points, bool robust = false);

/// @brief The box equal to [min_bound, max_bound] (R = I). @throws InvalidArgument on non-finite or max < min.
OrientedBoundingBox obb_from_aabb(const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound);

/// @brief The 8 corners in Open3D's GetBoxPoints order: ---, +--, -+-, --+, +++, -++, +-+, ++- (signs of the
/// offsets along R's columns).
std::array<Eigen::Vector3d, 8> box_points(const OrientedBoundingBox& box);

/// @brief InvalidArgument unless the box is finite, has extents >= 0 and R is orthonormal (1e-6).
void validate_obb(const OrientedBoundingBox& box);

/// @brief Ascending indices of the points inside the box, boundary included (|R^T (p - c)| <= extent / 2 on
/// every axis, with 16 ulps of slack at the box's scale so a set's box always holds the set's own extreme
/// points, which Open3D's exact test may lose to rounding); a NaN point is never inside. @throws InvalidArgument on an invalid box.
std::vector<int64_t> indices_in_obb(const std::vector<Eigen::Vector3d>& points, const OrientedBoundingBox& box);

/// @brief The points inside the box (outside when `invert`), with their attributes (PointCloud.crop).
/// @throws InvalidArgument on an invalid box or one of zero volume (Open3D: "zeros size").
PointCloud crop_obb(const PointCloud& cloud, const OrientedBoundingBox& box, bool invert = false);

/// @brief Triangles whose three vertices are inside the box, the vertices they use in order (with normals and
/// colors), per-triangle attributes and textures kept (TriangleMesh.crop). @throws as crop_obb, or on bad triangles.
TriangleMesh crop_obb(const TriangleMesh& mesh, const OrientedBoundingBox& box);

}  // namespace o3d::geometry
