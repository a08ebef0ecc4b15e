// SPDX-License-Identifier: MIT
#include "o3d/registration/estimation_colored.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <string>

#include "o3d/kdtree/query_order.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

void check_colored_inputs(const geometry::PointCloud& source, const geometry::PointCloud& target,
                          const std::vector<Eigen::Vector3d>& target_gradients, const CorrespondenceSet& corres,
                          double lambda_geometric) {
    if (!source.has_colors()) throw InvalidArgument("colored ICP needs source colors");
    if (!target.has_colors()) throw InvalidArgument("colored ICP needs target colors");
    if (!target.has_normals()) throw InvalidArgument("colored ICP needs target normals");
    if (target_gradients.size() != target.size())
        throw InvalidArgument("got " + std::to_string(target_gradients.size()) + " color gradients for " +
                              std::to_string(target.size()) + " target points");
    detail::check_lambda_geometric(lambda_geometric);
    detail::check_correspondences(corres, source.size(), target.size());
}

double intensity(const Eigen::Vector3d& c) { return (c(0) + c(1) + c(2)) / 3.0; }

}  // namespace

namespace detail {

void check_lambda_geometric(double lambda_geometric) {
    if (!(lambda_geometric >= 0.0 && lambda_geometric <= 1.0))
        throw InvalidArgument("lambda_geometric must be in [0, 1], got " + std::to_string(lambda_geometric));
}

}  // namespace detail

std::vector<double> color_intensities(const std::vector<Eigen::Vector3d>& colors) {
    std::vector<double> out(colors.size());
    for (size_t i = 0; i < colors.size(); ++i) out[i] = intensity(colors[i]);
    return out;
}

std::vector<Eigen::Vector3d> compute_color_gradients(const geometry::PointCloud& target, const kdtree::KDTree& tree,
                                                     double radius, int max_nn, int num_threads) {
    if (!target.has_colors()) throw InvalidArgument("color gradients need target colors");
    if (!target.has_normals()) throw InvalidArgument("color gradients need target normals");
    if (tree.size() != target.size())
        throw InvalidArgument("the tree indexes " + std::to_string(tree.size()) + " points but the target has " +
                              std::to_string(target.size()));
    if (!(radius > 0.0) || max_nn <= 0)
        throw InvalidArgument("color gradient search needs radius > 0 and max_nn > 0, got " + std::to_string(radius) +
                              ", " + std::to_string(max_nn));
    const auto& points = target.points;
    const auto& normals = target.normals;
    const std::vector<double> intensities = color_intensities(target.colors);
    const size_t n = points.size();
    std::vector<Eigen::Vector3d> gradients(n, Eigen::Vector3d::Zero());
    // Each gradient depends only on its own neighbourhood, so any schedule gives the same output;
    // the spatial order keeps shared tree nodes in cache.
    const std::vector<uint32_t> order = kdtree::spatial_order(points);
    const int threads = utility::resolve_num_threads(num_threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 256)
        for (int64_t s = 0; s < static_cast<int64_t>(n); ++s) {
            const size_t k = order[static_cast<size_t>(s)];
            const Eigen::Vector3d& p = points[k];
            const Eigen::Vector3d& nk = normals[k];
            const int found = tree.search_hybrid(p, radius, max_nn, idx, d2);
            if (found < 4 || !nk.allFinite()) continue;
            // Normal equations of the overdetermined system: one row per neighbour (the first hit is the
            // point itself and is skipped, as Open3D does), then (found - 1) * n . g = 0. The rows are the
            // raw offsets q - p, as in Open3D 0.20 (the paper and older releases project q onto the tangent
            // plane first; the heavy constraint row keeps g in the plane either way, and the two differ by
            // ~1e-4 relative on real scans).
            Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
            Eigen::Vector3d atb = Eigen::Vector3d::Zero();
            for (int j = 1; j < found; ++j) {
                const Eigen::Vector3d a = points[static_cast<size_t>(idx[j])] - p;
                ata.noalias() += a * a.transpose();
                atb += a * (intensities[static_cast<size_t>(idx[j])] - intensities[k]);
            }
            const double spread = ata.trace();  // sum of squared offsets: the neighbourhood's size
            const Eigen::Vector3d c = static_cast<double>(found - 1) * nk;
            ata.noalias() += c * c.transpose();
            // Neighbours on a line through p leave the gradient undetermined across it: the solve then returns
            // gradients thousands of times too large, and one such target point can throw colored ICP off (seen
            // on voxel-down-sampled fragments). Such a point keeps a zero gradient, as one with too few
            // neighbours does. The smallest eigenvalue against the neighbourhood's spread says how far from a
            // line the neighbours are (LDLT pivots do not: they stay well above it).
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
            eigen.computeDirect(ata, Eigen::EigenvaluesOnly);
            if (!(eigen.eigenvalues()(0) > 1e-6 * spread)) continue;
            const Eigen::Vector3d g = ata.ldlt().solve(atb);
            if (g.allFinite()) gradients[k] = g;
        }
    }
    return gradients;
}

Eigen::Matrix4d estimate_colored(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                 const std::vector<Eigen::Vector3d>& target_gradients, const CorrespondenceSet& corres,
                                 double lambda_geometric, const RobustKernel& kernel) {
    check_colored_inputs(source, target, target_gradients, corres, lambda_geometric);
    check_robust_kernel(kernel);
    const detail::ColoredRows rows(lambda_geometric);
    detail::ColoredSums sums;
    for (const auto& c : corres)
        sums.accumulate(rows, source.points[c(0)], intensity(source.colors[c(0)]), target.points[c(1)],
                        target.normals[c(1)], target_gradients[c(1)], intensity(target.colors[c(1)]), kernel);
    return detail::solve_point_to_plane(sums);
}

double colored_residual(const geometry::PointCloud& source, const geometry::PointCloud& target,
                        const std::vector<Eigen::Vector3d>& target_gradients, const CorrespondenceSet& corres,
                        double lambda_geometric) {
    check_colored_inputs(source, target, target_gradients, corres, lambda_geometric);
    const detail::ColoredRows rows(lambda_geometric);
    double sum = 0.0;
    for (const auto& c : corres) {
        double jg[6], jc[6], rg, rc;
        rows.rows(source.points[c(0)], intensity(source.colors[c(0)]), target.points[c(1)], target.normals[c(1)],
                  target_gradients[c(1)], intensity(target.colors[c(1)]), jg, rg, jc, rc);
        sum += rg * rg + rc * rc;
    }
    return sum;
}

}  // namespace o3d::registration
