// SPDX-License-Identifier: MIT
#pragma once
/// @file correspondence_checker.h
/// @brief Cheap tests that prune RANSAC hypotheses before they are scored (Open3D's
/// CorrespondenceCheckerBasedOnEdgeLength / BasedOnDistance / BasedOnNormal).
#include <Eigen/Core>
#include <cstddef>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief One correspondence checker: a kind and its threshold.
class CorrespondenceChecker {
public:
    enum class Kind { EdgeLength, Distance, Normal };

    /// @brief Every edge between two drawn source points and the edge between their target partners
    /// must have similar lengths: neither is shorter than `similarity_threshold` times the other.
    /// Needs no transformation. @throws o3d::InvalidArgument unless 0 < similarity_threshold <= 1.
    static CorrespondenceChecker edge_length(double similarity_threshold = 0.9);
    /// @brief Every moved source point lies within `distance_threshold` of its target partner.
    /// @throws o3d::InvalidArgument unless distance_threshold is finite and > 0.
    static CorrespondenceChecker distance(double distance_threshold);
    /// @brief Every source normal, turned by the transformation's linear part, makes an angle of at
    /// most `normal_angle_threshold` (radians) with its target partner's normal (their dot product is
    /// at least its cosine). Both clouds need normals.
    /// @throws o3d::InvalidArgument unless normal_angle_threshold is finite and > 0.
    static CorrespondenceChecker normal(double normal_angle_threshold);

    Kind kind() const { return kind_; }
    double threshold() const { return threshold_; }
    /// @brief Whether the test looks at the transformation (Open3D's require_pointcloud_alignment_).
    bool requires_alignment() const { return kind_ != Kind::EdgeLength; }

    /// @brief Does the hypothesis `transformation` (moving the source) built from `corres` pass?
    /// @see o3d.pipelines.registration.CorrespondenceChecker.Check
    /// @throws o3d::InvalidArgument on an index out of range, a non-finite transformation, or the
    /// normal checker on a cloud without normals (where Open3D only warns and passes).
    bool check(const geometry::PointCloud& source, const geometry::PointCloud& target,
               const CorrespondenceSet& corres,
               const Eigen::Matrix4d& transformation = Eigen::Matrix4d::Identity()) const;

    /// @brief check() without argument validation, on `n` pairs: for callers that validated the
    /// indices (and normals) once, such as RANSAC's inner loop.
    bool passes(const geometry::PointCloud& source, const geometry::PointCloud& target, const Eigen::Vector2i* corres,
                size_t n, const Eigen::Matrix4d& transformation) const;

private:
    CorrespondenceChecker(Kind kind, double threshold) : kind_(kind), threshold_(threshold) {}

    Kind kind_;
    double threshold_;
};

}  // namespace o3d::registration
