// SPDX-License-Identifier: MIT
#include "o3d/color_map/pose_step.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>

namespace o3d::color_map::detail {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Fewer residuals than unknowns of a pose cannot determine it.
constexpr int kMinResiduals = 6;
/// Negligible against any residual's curvature (intensities in [0, 1], gradients per pixel).
constexpr double kMinAnchorCurvature = 1e-9;

/// One vertex's residual and its derivatives: by the pose twist (rotation, translation), and, with a warp,
/// by the offsets of the four anchors around it (d r / d offset_k = weight_k * image gradient).
struct Linearisation {
    double r = 0.0;
    Vector6d pose;
    Eigen::Vector2d gradient;
};

/// The residual of vertex `x` at `view`; false when it cannot be sampled.
bool linearise(const View& view, const ViewImages& images, const Eigen::Vector3d& x, double proxy,
               Projection& pr, Linearisation& out) {
    if (!project(view, x, pr) || !images.intensity.can_sample(pr.pixel.x(), pr.pixel.y())) return false;
    const double u = pr.pixel.x(), v = pr.pixel.y();
    out.r = images.intensity.sample(u, v) - proxy;
    out.gradient = {images.dx.sample(u, v), images.dy.sample(u, v)};
    // d pixel / d camera point of the pinhole; the warp's own dependence on the pixel is neglected (its
    // offsets vary slowly across a grid cell), so the same derivative serves the warped pixel.
    const Eigen::Vector3d& p = pr.point;
    const double iz = 1.0 / p.z();
    const double fx = view.intrinsic.fx, fy = view.intrinsic.fy;
    const Eigen::Vector3d a(out.gradient.x() * fx * iz, out.gradient.y() * fy * iz,
                            -(out.gradient.x() * fx * p.x() + out.gradient.y() * fy * p.y()) * iz * iz);
    // A left twist moves p by w x p + t: d r / d w = p x a, d r / d t = a.
    out.pose.head<3>() = p.cross(a);
    out.pose.tail<3>() = a;
    return true;
}

/// Compose the twist's motion on the left of the world-to-camera pose.
void apply_twist(View& view, const Vector6d& delta) {
    const Eigen::Vector3d w = delta.head<3>();
    const double angle = w.norm();
    Eigen::Matrix4d motion = Eigen::Matrix4d::Identity();
    if (angle > 0.0) motion.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
    motion.topRightCorner<3, 1>() = delta.tail<3>();
    view.extrinsic = motion * view.extrinsic;
}

StepStatistics rigid_step(View& view, const ViewImages& images, const std::vector<int>& visible,
                          const std::vector<Eigen::Vector3d>& vertices, const std::vector<double>& proxy) {
    StepStatistics stats;
    Matrix6d h = Matrix6d::Zero();
    Vector6d b = Vector6d::Zero();
    Projection pr;
    Linearisation lin;
    for (int i : visible) {
        if (!linearise(view, images, vertices[size_t(i)], proxy[size_t(i)], pr, lin)) continue;
        h.selfadjointView<Eigen::Upper>().rankUpdate(lin.pose);
        b += lin.r * lin.pose;
        stats.squared_error += lin.r * lin.r;
        ++stats.residuals;
    }
    if (stats.residuals < kMinResiduals) return stats;
    const Eigen::LDLT<Matrix6d> ldlt(h.selfadjointView<Eigen::Upper>());
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return stats;
    const Vector6d delta = -ldlt.solve(b);
    if (delta.allFinite()) apply_twist(view, delta);
    return stats;
}

/// Pose and warp together. Each residual couples the pose with only four anchors, so the normal matrix is
/// sparse apart from its six pose rows; a sparse LDLT (fill-reducing order) solves it in a fraction of the
/// time a dense one would take with Open3D's default 16 x 21 anchors.
StepStatistics non_rigid_step(View& view, const ViewImages& images, const std::vector<int>& visible,
                              const std::vector<Eigen::Vector3d>& vertices, const std::vector<double>& proxy,
                              double anchor_weight) {
    StepStatistics stats;
    const int n = 6 + 2 * view.warp.size();
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    Projection pr;
    Linearisation lin;
    std::array<int, 14> index;
    std::array<double, 14> jac;
    for (int i : visible) {
        if (!linearise(view, images, vertices[size_t(i)], proxy[size_t(i)], pr, lin)) continue;
        for (int k = 0; k < 6; ++k) {
            index[size_t(k)] = k;
            jac[size_t(k)] = lin.pose[k];
        }
        for (int k = 0; k < 4; ++k)
            for (int d = 0; d < 2; ++d) {
                index[size_t(6 + 2 * k + d)] = 6 + 2 * pr.cell.anchor[size_t(k)] + d;
                jac[size_t(6 + 2 * k + d)] = pr.cell.weight[size_t(k)] * lin.gradient[d];
            }
        for (size_t r = 0; r < index.size(); ++r) {
            b[index[r]] += jac[r] * lin.r;
            for (size_t c = 0; c < index.size(); ++c) h(index[r], index[c]) += jac[r] * jac[c];
        }
        stats.squared_error += lin.r * lin.r;
        ++stats.residuals;
    }
    if (stats.residuals < kMinResiduals) return stats;
    // The regulariser lambda^2 * ||offset||^2; its floor keeps an anchor no residual reaches determined (it then
    // stays put) when lambda is 0.
    const double w2 = std::max(anchor_weight * anchor_weight, kMinAnchorCurvature);
    for (int a = 0; a < view.warp.size(); ++a)
        for (int d = 0; d < 2; ++d) {
            h(6 + 2 * a + d, 6 + 2 * a + d) += w2;
            b[6 + 2 * a + d] += w2 * view.warp.offset(a)[d];
        }
    const Eigen::SparseMatrix<double> sparse = h.sparseView();
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(sparse);
    if (ldlt.info() != Eigen::Success) return stats;
    const Eigen::VectorXd delta = -ldlt.solve(b);
    if (ldlt.info() != Eigen::Success || !delta.allFinite()) return stats;
    apply_twist(view, delta.head<6>());
    for (int a = 0; a < view.warp.size(); ++a) view.warp.offset(a) += delta.segment<2>(6 + 2 * a);
    return stats;
}

}  // namespace

StepStatistics gauss_newton_step(View& view, const ViewImages& images, const std::vector<int>& visible,
                                 const std::vector<Eigen::Vector3d>& vertices, const std::vector<double>& proxy,
                                 double anchor_weight) {
    if (view.warp.empty()) return rigid_step(view, images, visible, vertices, proxy);
    return non_rigid_step(view, images, visible, vertices, proxy, anchor_weight);
}

}  // namespace o3d::color_map::detail
