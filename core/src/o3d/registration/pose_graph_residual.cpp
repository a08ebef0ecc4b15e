// SPDX-License-Identifier: MIT
#include "o3d/registration/pose_graph_residual.h"

#include <Eigen/LU>
#include <cmath>
#include <cstdint>

#include "o3d/registration/pose_graph_system.h"

namespace o3d::registration::detail {
namespace {

/// Below this many edges a parallel region costs more than the work it splits (an edge's error is ~0.1 us,
/// its Jacobian blocks ~0.5 us), and on a loaded machine a region's barrier can cost milliseconds.
constexpr size_t kMinParallelEdges = 1024;

/// lin(u v^T) for the 4-vectors u (a column) and v (a row): lin(M) = ((M21 - M12) / 2, (M02 - M20) / 2,
/// (M10 - M01) / 2, M03, M13, M23) is Choi et al.'s small-motion reading of a near-identity transform.
inline Vector6d lin_outer(const Eigen::Vector4d& u, const Eigen::RowVector4d& v) {
    Vector6d out;
    out << (u(2) * v(1) - u(1) * v(2)) / 2.0, (u(0) * v(2) - u(2) * v(0)) / 2.0, (u(1) * v(0) - u(0) * v(1)) / 2.0,
        u(0) * v(3), u(1) * v(3), u(2) * v(3);
    return out;
}

/// lin(P S).
inline Vector6d edge_error(const Eigen::Matrix4d& p, const Eigen::Matrix4d& s) {
    const Eigen::Matrix4d m = p * s;
    Vector6d out;
    out << (m(2, 1) - m(1, 2)) / 2.0, (m(0, 2) - m(2, 0)) / 2.0, (m(1, 0) - m(0, 1)) / 2.0, m(0, 3), m(1, 3), m(2, 3);
    return out;
}

/// d e / d(source step) at a zero step: column k is lin(P G_k S), G_k the generator of the k-th step
/// coordinate (rotations about x, y, z, then translations). P G_k S is a sum of outer products of P's
/// columns and S's rows, which avoids the 4x4 products. The target Jacobian is its negative, since a
/// common step of both nodes leaves the error unchanged.
inline Eigen::Matrix<double, 6, 6> source_jacobian(const Eigen::Matrix4d& p, const Eigen::Matrix4d& s) {
    const Eigen::Vector4d p0 = p.col(0), p1 = p.col(1), p2 = p.col(2);
    const Eigen::RowVector4d s0 = s.row(0), s1 = s.row(1), s2 = s.row(2), s3 = s.row(3);
    Eigen::Matrix<double, 6, 6> j;
    j.col(0) = lin_outer(p2, s1) - lin_outer(p1, s2);
    j.col(1) = lin_outer(p0, s2) - lin_outer(p2, s0);
    j.col(2) = lin_outer(p1, s0) - lin_outer(p0, s1);
    j.col(3) = lin_outer(p0, s3);
    j.col(4) = lin_outer(p1, s3);
    j.col(5) = lin_outer(p2, s3);
    return j;
}

}  // namespace

Eigen::Matrix4d step_transform(const Vector6d& d) {
    const double ca = std::cos(d(0)), sa = std::sin(d(0));
    const double cb = std::cos(d(1)), sb = std::sin(d(1));
    const double cg = std::cos(d(2)), sg = std::sin(d(2));
    Eigen::Matrix4d t;
    // Rz(g) Ry(b) Rx(a), written out.
    t << cg * cb, cg * sb * sa - sg * ca, cg * sb * ca + sg * sa, d(3),  //
        sg * cb, sg * sb * sa + cg * ca, sg * sb * ca - cg * sa, d(4),   //
        -sb, cb * sa, cb * ca, d(5),                                     //
        0.0, 0.0, 0.0, 1.0;
    return t;
}

double pose_vector_squared_norm(const Eigen::Matrix4d& pose) {
    const double r00 = pose(0, 0), r10 = pose(1, 0), r20 = pose(2, 0);
    const double sy = std::sqrt(r00 * r00 + r10 * r10);
    double x, y, z;
    if (!(sy < 1e-6)) {
        x = std::atan2(pose(2, 1), pose(2, 2));
        y = std::atan2(-r20, sy);
        z = std::atan2(r10, r00);
    } else {  // gimbal lock: fold the z rotation into x
        x = std::atan2(-pose(1, 2), pose(1, 1));
        y = std::atan2(-r20, sy);
        z = 0.0;
    }
    return x * x + y * y + z * z + pose.block<3, 1>(0, 3).squaredNorm();
}

PoseGraphObjective::PoseGraphObjective(const std::vector<PoseGraphEdge>& edges, double mu, int num_threads)
    : edges_(edges), mu_(mu), num_threads_(num_threads) {
    measurement_inverse_.reserve(edges.size());
    confidence_.reserve(edges.size());
    for (const auto& e : edges) {
        measurement_inverse_.push_back(e.transformation.inverse());
        confidence_.push_back(e.confidence);
    }
}

bool PoseGraphObjective::parallel() const { return num_threads_ > 1 && edges_.size() >= kMinParallelEdges; }

const Poses& PoseGraphObjective::inverses(const Poses& poses) {
    inverse_.resize(poses.size());
    for (size_t i = 0; i < poses.size(); ++i) inverse_[i] = poses[i].inverse();
    return inverse_;
}

void PoseGraphObjective::errors(const Poses& poses, EdgeErrors& out) {
    const Poses& inv = inverses(poses);
    const int64_t n = static_cast<int64_t>(edges_.size());
    out.resize(edges_.size());
#pragma omp parallel for schedule(static) num_threads(num_threads_) if (parallel())
    for (int64_t k = 0; k < n; ++k) {
        const size_t i = static_cast<size_t>(k);
        const PoseGraphEdge& e = edges_[i];
        const Eigen::Matrix4d p = measurement_inverse_[i] * inv[static_cast<size_t>(e.target_node_id)];
        out[i] = edge_error(p, poses[static_cast<size_t>(e.source_node_id)]);
    }
}

double PoseGraphObjective::residual(const EdgeErrors& errors) {
    const int64_t n = static_cast<int64_t>(edges_.size());
    // Serial: ~50 ns an edge is less than a parallel region costs until far beyond real graph sizes.
    double sum = 0.0;
    for (int64_t k = 0; k < n; ++k) {
        const size_t i = static_cast<size_t>(k);
        const Vector6d& e = errors[i];
        const double l = confidence_[i];
        const double root = std::sqrt(l) - 1.0;
        sum += l * e.dot(edges_[i].information * e) + mu_ * root * root;
    }
    return sum;
}

void PoseGraphObjective::update_confidences(const EdgeErrors& errors) {
    for (size_t i = 0; i < edges_.size(); ++i) {
        if (!edges_[i].uncertain) continue;
        const double r2 = errors[i].dot(edges_[i].information * errors[i]);
        const double w = mu_ / (mu_ + r2);
        confidence_[i] = w * w;
    }
}

void PoseGraphObjective::linearize(const Poses& poses, const EdgeErrors& errors, NormalEquations& system) {
    const Poses& inv = inverses(poses);
    const int64_t n = static_cast<int64_t>(edges_.size());
    blocks_.resize(edges_.size());
#pragma omp parallel for schedule(static) num_threads(num_threads_) if (parallel())
    for (int64_t k = 0; k < n; ++k) {
        const size_t i = static_cast<size_t>(k);
        const PoseGraphEdge& e = edges_[i];
        const Eigen::Matrix4d p = measurement_inverse_[i] * inv[static_cast<size_t>(e.target_node_id)];
        const Eigen::Matrix<double, 6, 6> js = source_jacobian(p, poses[static_cast<size_t>(e.source_node_id)]);
        const Eigen::Matrix<double, 6, 6> info_js = e.information * js;
        const double l = confidence_[i];
        blocks_[i].hessian.noalias() = l * (js.transpose() * info_js);
        blocks_[i].gradient.noalias() = l * (js.transpose() * (e.information.transpose() * errors[i]));
    }
    system.clear();
    for (size_t i = 0; i < edges_.size(); ++i) system.add_edge(i, blocks_[i].hessian, blocks_[i].gradient);
}

}  // namespace o3d::registration::detail
