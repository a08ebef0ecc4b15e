// SPDX-License-Identifier: MIT
#include "o3d/registration/estimation_point_to_plane.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::registration {
namespace detail {

Eigen::Matrix4d solve_point_to_plane(const PointToPlaneSums& sums) {
    Eigen::Matrix<double, 6, 6> jtj;
    Eigen::Matrix<double, 6, 1> jtr;
    int k = 0;
    for (int a = 0; a < 6; ++a) {
        for (int b = a; b < 6; ++b) jtj(a, b) = jtj(b, a) = sums.jtj[k++];
        jtr(a) = sums.jtr[a];
    }
    Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
    const Eigen::Matrix<double, 6, 1> x = jtj.ldlt().solve(-jtr);
    if (!x.allFinite()) return out;
    out.topLeftCorner<3, 3>() = (Eigen::AngleAxisd(x(2), Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(x(1), Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(x(0), Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
    out.topRightCorner<3, 1>() = x.tail<3>();
    return out;
}

}  // namespace detail

Eigen::Matrix4d estimate_point_to_plane(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                        const CorrespondenceSet& corres) {
    if (!target.has_normals()) throw InvalidArgument("point-to-plane estimation needs target normals");
    detail::PointToPlaneSums sums;
    for (const auto& c : corres) {
        if (c(0) < 0 || static_cast<size_t>(c(0)) >= source.size() || c(1) < 0 ||
            static_cast<size_t>(c(1)) >= target.size())
            throw InvalidArgument("correspondence (" + std::to_string(c(0)) + ", " + std::to_string(c(1)) +
                                  ") is out of range");
        sums.accumulate(source.points[c(0)], target.points[c(1)], target.normals[c(1)]);
    }
    return detail::solve_point_to_plane(sums);
}

}  // namespace o3d::registration
