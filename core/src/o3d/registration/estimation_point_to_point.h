// SPDX-License-Identifier: MIT
#pragma once
/// @file estimation_point_to_point.h
/// @brief Closed-form rigid (optionally similarity) fit of paired points: Umeyama (1991), which
/// Open3D's TransformationEstimationPointToPoint uses through Eigen::umeyama.
#include <Eigen/Core>
#include <cstdint>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief The transformation that best maps `source[c(0)]` onto `target[c(1)]` in the least-squares
/// sense (rotation + translation, times a uniform scale when `with_scaling`). Identity when `corres`
/// is empty. @see o3d.pipelines.registration.TransformationEstimationPointToPoint.compute_transformation
/// @throws o3d::InvalidArgument on an index out of range.
Eigen::Matrix4d estimate_point_to_point(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                        const CorrespondenceSet& corres, bool with_scaling = false);

namespace detail {

/// @brief One-pass moments of the pairs, taken relative to a fixed `reference` point so that clouds
/// far from the origin do not lose precision to cancellation.
struct PointToPointSums {
    int64_t count = 0;
    Eigen::Vector3d source_sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d target_sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d cross = Eigen::Matrix3d::Zero();  ///< sum of target * source^T
    double source_norm2 = 0.0;                        ///< sum of |source|^2 (for the scale)

    void accumulate(const Eigen::Vector3d& s, const Eigen::Vector3d& t) {
        ++count;
        source_sum += s;
        target_sum += t;
        cross.noalias() += t * s.transpose();
        source_norm2 += s.squaredNorm();
    }
    void add(const PointToPointSums& o) {
        count += o.count;
        source_sum += o.source_sum;
        target_sum += o.target_sum;
        cross += o.cross;
        source_norm2 += o.source_norm2;
    }
};

/// @brief Umeyama's solution from the moments (points were taken relative to `reference`).
Eigen::Matrix4d solve_point_to_point(const PointToPointSums& sums, const Eigen::Vector3d& reference,
                                     bool with_scaling);

}  // namespace detail
}  // namespace o3d::registration
