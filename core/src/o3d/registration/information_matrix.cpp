// SPDX-License-Identifier: MIT
#include "o3d/registration/information_matrix.h"

#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/correspondence_pass.h"
#include "o3d/registration/validation.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

/// G^T G summed over pairs depends only on the first and second moments of the target points,
/// so ten scalars replace 36 per pair.
struct TargetMoments {
    double x = 0, y = 0, z = 0, xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;

    void accumulate(const Eigen::Vector3d& q) {
        x += q(0);
        y += q(1);
        z += q(2);
        xx += q(0) * q(0);
        xy += q(0) * q(1);
        xz += q(0) * q(2);
        yy += q(1) * q(1);
        yz += q(1) * q(2);
        zz += q(2) * q(2);
    }
    void add(const TargetMoments& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        xx += o.xx;
        xy += o.xy;
        xz += o.xz;
        yy += o.yy;
        yz += o.yz;
        zz += o.zz;
    }
};

}  // namespace

Eigen::Matrix<double, 6, 6> get_information_matrix_from_point_clouds(const geometry::PointCloud& source,
                                                                     const geometry::PointCloud& target,
                                                                     double max_correspondence_distance,
                                                                     const Eigen::Matrix4d& transformation,
                                                                     int num_threads) {
    detail::check_registration_inputs(source, target, max_correspondence_distance, transformation, num_threads);
    const kdtree::KDTree tree(target.points);
    const auto& points = target.points;
    detail::PassWorkspace<TargetMoments> ws;
    const auto totals = detail::correspondence_pass<TargetMoments>(
        source.points, transformation, tree, max_correspondence_distance, utility::resolve_num_threads(num_threads),
        ws, [&](TargetMoments& m, const Eigen::Vector3d&, int index) { m.accumulate(points[index]); });

    const TargetMoments& m = totals.sums;
    const double n = static_cast<double>(totals.count);
    Eigen::Matrix<double, 6, 6> info;
    // Rotation block: sum of (|q|^2 I - q q^T).
    info(0, 0) = m.yy + m.zz;
    info(1, 1) = m.xx + m.zz;
    info(2, 2) = m.xx + m.yy;
    info(0, 1) = info(1, 0) = -m.xy;
    info(0, 2) = info(2, 0) = -m.xz;
    info(1, 2) = info(2, 1) = -m.yz;
    // Rotation-translation block: sum of [q]x (its transpose below the diagonal).
    Eigen::Matrix3d cross;
    cross << 0.0, -m.z, m.y, m.z, 0.0, -m.x, -m.y, m.x, 0.0;
    info.topRightCorner<3, 3>() = cross;
    info.bottomLeftCorner<3, 3>() = cross.transpose();
    info.bottomRightCorner<3, 3>() = n * Eigen::Matrix3d::Identity();
    return info;
}

}  // namespace o3d::registration
