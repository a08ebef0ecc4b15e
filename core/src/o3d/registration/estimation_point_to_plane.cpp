// SPDX-License-Identifier: MIT
#include "o3d/registration/estimation_point_to_plane.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::registration {
namespace detail {

Eigen::Matrix<double, 6, 1> NormalEquations6::solve() const {
    Eigen::Matrix<double, 6, 6> a;
    Eigen::Matrix<double, 6, 1> b;
    int k = 0;
    for (int r = 0; r < 6; ++r) {
        for (int c = r; c < 6; ++c) a(r, c) = a(c, r) = jtj[k++];
        b(r) = jtr[r];
    }
    return a.ldlt().solve(-b);
}

Eigen::Matrix4d euler_pose_to_matrix(const Eigen::Matrix<double, 6, 1>& x) {
    Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
    if (!x.allFinite()) return out;
    out.topLeftCorner<3, 3>() = (Eigen::AngleAxisd(x(2), Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(x(1), Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(x(0), Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
    out.topRightCorner<3, 1>() = x.tail<3>();
    return out;
}

void check_correspondences(const CorrespondenceSet& corres, size_t num_source, size_t num_target) {
    for (const auto& c : corres)
        if (c(0) < 0 || static_cast<size_t>(c(0)) >= num_source || c(1) < 0 ||
            static_cast<size_t>(c(1)) >= num_target)
            throw InvalidArgument("correspondence (" + std::to_string(c(0)) + ", " + std::to_string(c(1)) +
                                  ") is out of range");
}

}  // namespace detail

Eigen::Matrix4d estimate_point_to_plane(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                        const CorrespondenceSet& corres, const RobustKernel& kernel) {
    if (!target.has_normals()) throw InvalidArgument("point-to-plane estimation needs target normals");
    check_robust_kernel(kernel);
    detail::check_correspondences(corres, source.size(), target.size());
    detail::PointToPlaneSums sums;
    for (const auto& c : corres)
        sums.accumulate(source.points[c(0)], target.points[c(1)], target.normals[c(1)], kernel);
    return detail::solve_point_to_plane(sums);
}

}  // namespace o3d::registration
