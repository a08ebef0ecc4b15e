// SPDX-License-Identifier: MIT
#include "o3d/registration/correspondence_checker.h"

#include <cmath>
#include <string>

#include "o3d/registration/estimation_point_to_plane.h"  // check_correspondences
#include "o3d/utility/error.h"

namespace o3d::registration {

namespace {

bool edge_lengths_similar(const geometry::PointCloud& source, const geometry::PointCloud& target,
                          const Eigen::Vector2i* corres, size_t n, double similarity) {
    // All pairs of drawn correspondences, not only consecutive ones (as Open3D).
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            const double ds = (source.points[corres[i](0)] - source.points[corres[j](0)]).norm();
            const double dt = (target.points[corres[i](1)] - target.points[corres[j](1)]).norm();
            if (ds < dt * similarity || dt < ds * similarity) return false;
        }
    return true;
}

bool distances_within(const geometry::PointCloud& source, const geometry::PointCloud& target,
                      const Eigen::Vector2i* corres, size_t n, const Eigen::Matrix4d& t, double threshold) {
    const Eigen::Matrix3d linear = t.topLeftCorner<3, 3>();
    const Eigen::Vector3d translation = t.topRightCorner<3, 1>();
    for (size_t k = 0; k < n; ++k) {
        const Eigen::Vector3d moved = linear * source.points[corres[k](0)] + translation;
        // Negated so that a NaN distance fails the test.
        if (!((target.points[corres[k](1)] - moved).norm() <= threshold)) return false;
    }
    return true;
}

bool normals_within(const geometry::PointCloud& source, const geometry::PointCloud& target,
                    const Eigen::Vector2i* corres, size_t n, const Eigen::Matrix4d& t, double angle) {
    const double min_cos = std::cos(angle);
    const Eigen::Matrix3d linear = t.topLeftCorner<3, 3>();
    for (size_t k = 0; k < n; ++k) {
        // A normal is a direction: only the linear part moves it (Open3D multiplies (n, 0)).
        const Eigen::Vector3d turned = linear * source.normals[corres[k](0)];
        if (!(target.normals[corres[k](1)].dot(turned) >= min_cos)) return false;
    }
    return true;
}

void require_positive(double threshold, const char* what) {
    if (!std::isfinite(threshold) || threshold <= 0.0)
        throw InvalidArgument(std::string(what) + " must be finite and > 0, got " + std::to_string(threshold));
}

}  // namespace

CorrespondenceChecker CorrespondenceChecker::edge_length(double similarity_threshold) {
    if (!(similarity_threshold > 0.0 && similarity_threshold <= 1.0))
        throw InvalidArgument("similarity_threshold must be in (0, 1], got " + std::to_string(similarity_threshold));
    return {Kind::EdgeLength, similarity_threshold};
}

CorrespondenceChecker CorrespondenceChecker::distance(double distance_threshold) {
    require_positive(distance_threshold, "distance_threshold");
    return {Kind::Distance, distance_threshold};
}

CorrespondenceChecker CorrespondenceChecker::normal(double normal_angle_threshold) {
    require_positive(normal_angle_threshold, "normal_angle_threshold");
    return {Kind::Normal, normal_angle_threshold};
}

bool CorrespondenceChecker::passes(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                   const Eigen::Vector2i* corres, size_t n,
                                   const Eigen::Matrix4d& transformation) const {
    switch (kind_) {
        case Kind::EdgeLength: return edge_lengths_similar(source, target, corres, n, threshold_);
        case Kind::Distance: return distances_within(source, target, corres, n, transformation, threshold_);
        case Kind::Normal: return normals_within(source, target, corres, n, transformation, threshold_);
    }
    return false;
}

bool CorrespondenceChecker::check(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                  const CorrespondenceSet& corres, const Eigen::Matrix4d& transformation) const {
    if (!transformation.allFinite()) throw InvalidArgument("transformation has a non-finite entry");
    detail::check_correspondences(corres, source.size(), target.size());
    if (kind_ == Kind::Normal && (!source.has_normals() || !target.has_normals()))
        throw InvalidArgument("the normal correspondence checker needs normals on both clouds");
    return passes(source, target, corres.data(), corres.size(), transformation);
}

}  // namespace o3d::registration
