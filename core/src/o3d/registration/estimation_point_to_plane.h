// SPDX-License-Identifier: MIT
#pragma once
/// @file estimation_point_to_plane.h
/// @brief Linearised point-to-plane step (Low 2004), as Open3D's TransformationEstimationPointToPlane:
/// minimise sum(((R s + t - q) . n_q)^2) with R ~ I + [w]x, solve the 6x6 normal equations, and
/// rebuild R = Rz(w_z) Ry(w_y) Rx(w_x).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross product
#include <cstdint>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief One Gauss-Newton step aligning `source[c(0)]` to the planes of `target[c(1)]`.
/// Identity when `corres` is empty or the system is singular.
/// @see o3d.pipelines.registration.TransformationEstimationPointToPlane.compute_transformation
/// @throws o3d::InvalidArgument when `target` has no normals or an index is out of range.
Eigen::Matrix4d estimate_point_to_plane(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                        const CorrespondenceSet& corres);

namespace detail {

/// @brief J^T J (upper triangle, row-major, 21 values) and J^T r with J = [s x n, n], r = (s - q) . n.
struct PointToPlaneSums {
    double jtj[21] = {};
    double jtr[6] = {};

    void accumulate(const Eigen::Vector3d& s, const Eigen::Vector3d& q, const Eigen::Vector3d& n) {
        const Eigen::Vector3d c = s.cross(n);
        const double j[6] = {c(0), c(1), c(2), n(0), n(1), n(2)};
        const double r = (s - q).dot(n);
        int k = 0;
        for (int a = 0; a < 6; ++a) {
            for (int b = a; b < 6; ++b) jtj[k++] += j[a] * j[b];
            jtr[a] += j[a] * r;
        }
    }
    void add(const PointToPlaneSums& o) {
        for (int k = 0; k < 21; ++k) jtj[k] += o.jtj[k];
        for (int k = 0; k < 6; ++k) jtr[k] += o.jtr[k];
    }
};

/// @brief Solve J^T J x = -J^T r (LDLT, as Open3D) and turn x = (w, t) into a 4x4.
/// Identity when the solution is not finite.
Eigen::Matrix4d solve_point_to_plane(const PointToPlaneSums& sums);

}  // namespace detail
}  // namespace o3d::registration
