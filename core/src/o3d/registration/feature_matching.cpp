// SPDX-License-Identifier: MIT
#include "o3d/registration/feature_matching.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "o3d/kdtree/kd_tree_xd.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

// Above this dimension the rotation below costs more than it saves.
constexpr Eigen::Index kMaxRotatedDimension = 128;

/// @brief Rows: the principal axes of the columns of `data`, by decreasing variance (an orthonormal basis).
Eigen::MatrixXd principal_axes(const Eigen::MatrixXd& data) {
    const Eigen::VectorXd mean = data.rowwise().mean();
    Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(data.rows(), data.rows());
    for (Eigen::Index i = 0; i < data.cols(); ++i) {
        const Eigen::VectorXd c = data.col(i) - mean;
        covariance.selfadjointView<Eigen::Lower>().rankUpdate(c);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);  // reads the lower triangle
    return solver.eigenvectors().rowwise().reverse().transpose();
}

/// @brief `axes` * data, one column at a time (a matrix-vector product each: no threads of its own).
Eigen::MatrixXd rotate(const Eigen::MatrixXd& axes, const Eigen::MatrixXd& data) {
    Eigen::MatrixXd out(data.rows(), data.cols());
    for (Eigen::Index i = 0; i < data.cols(); ++i) out.col(i).noalias() = axes * data.col(i);
    return out;
}

double squared_distance(const double* a, const double* b, Eigen::Index dim) {
    double sum = 0.0;
    for (Eigen::Index d = 0; d < dim; ++d) sum += (a[d] - b[d]) * (a[d] - b[d]);
    return sum;
}

/// @brief For each descriptor of `queries`, the index of the nearest descriptor of `reference` (exact
/// L2; equal distances go to the smaller index).
///
/// The search runs in the reference's principal axes: FPFH bins are strongly correlated, and a KD-tree
/// prunes far better when its first splits follow the directions of largest spread (about 2.5x fewer
/// visits on the shared scans). A rotation changes squared distances only by rounding, bounded here by
/// `tolerance`: when the two nearest in the rotated space are farther apart than twice that, the first
/// is the true nearest; otherwise every candidate within the tolerance is compared in the original values.
std::vector<int32_t> nearest_descriptors(const Feature& queries, const Feature& reference, int num_threads) {
    const Eigen::Index dim = reference.data.rows();
    const bool rotated = dim > 1 && dim <= kMaxRotatedDimension;
    const Eigen::MatrixXd axes = rotated ? principal_axes(reference.data) : Eigen::MatrixXd();
    const Eigen::MatrixXd reference_rotated = rotated ? rotate(axes, reference.data) : Eigen::MatrixXd();
    const Eigen::MatrixXd queries_rotated = rotated ? rotate(axes, queries.data) : Eigen::MatrixXd();
    const Eigen::MatrixXd& ref = rotated ? reference_rotated : reference.data;
    const Eigen::MatrixXd& qry = rotated ? queries_rotated : queries.data;

    const kdtree::KDTreeXd tree(ref);
    const kdtree::SearchResult two =
        tree.search_batch(qry.data(), static_cast<size_t>(qry.cols()), kdtree::SearchParam::make_knn(2), num_threads);
    const double largest_reference = reference.data.colwise().squaredNorm().maxCoeff();

    const int64_t n = queries.data.cols();
    std::vector<int32_t> nearest(static_cast<size_t>(n));
    const int threads = utility::resolve_num_threads(num_threads);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> candidates;
        std::vector<double> distances2;
#pragma omp for schedule(dynamic, 256)
        for (int64_t q = 0; q < n; ++q) {
            const int64_t b = two.offsets[q], e = two.offsets[q + 1];
            const int32_t first = two.indices[static_cast<size_t>(b)];
            if (!rotated) {
                nearest[static_cast<size_t>(q)] = first;
                continue;
            }
            // Rounding of the rotation: a few hundred ulps of the squared norms involved; 1e-11 is
            // a thousandfold margin.
            const double first_d2 = two.distances2[static_cast<size_t>(b)];
            const double tolerance = 1e-11 * (queries.data.col(q).squaredNorm() + largest_reference + first_d2);
            if (e - b < 2 || two.distances2[static_cast<size_t>(b) + 1] - first_d2 > 2.0 * tolerance) {
                nearest[static_cast<size_t>(q)] = first;
                continue;
            }
            tree.search_radius(qry.col(q).data(), std::sqrt(first_d2 + 2.0 * tolerance) * (1.0 + 1e-12), candidates,
                               distances2);
            int32_t best = -1;
            double best_d2 = std::numeric_limits<double>::infinity();
            for (int c : candidates) {
                const double d2 = squared_distance(queries.data.col(q).data(), reference.data.col(c).data(), dim);
                if (d2 < best_d2 || (d2 == best_d2 && c < best)) {
                    best = c;
                    best_d2 = d2;
                }
            }
            nearest[static_cast<size_t>(q)] = best >= 0 ? best : first;
        }
    }
    return nearest;
}

}  // namespace

CorrespondenceSet correspondences_from_features(const Feature& source, const Feature& target, bool mutual_filter,
                                                double mutual_consistency_ratio, int num_threads) {
    if (source.dimension() != target.dimension())
        throw InvalidArgument("source features have dimension " + std::to_string(source.dimension()) +
                              " but target features " + std::to_string(target.dimension()));
    if (source.num() == 0 || target.num() == 0 || source.dimension() == 0)
        throw InvalidArgument("cannot match an empty feature (source " + std::to_string(source.dimension()) + " x " +
                              std::to_string(source.num()) + ", target " + std::to_string(target.dimension()) +
                              " x " + std::to_string(target.num()) + ")");
    if (!(mutual_consistency_ratio >= 0.0 && mutual_consistency_ratio <= 1.0))
        throw InvalidArgument("mutual_consistency_ratio must be in [0, 1], got " +
                              std::to_string(mutual_consistency_ratio));
    if (num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(num_threads));
    if (!source.data.allFinite() || !target.data.allFinite())
        throw InvalidArgument("the features hold a non-finite value");

    const std::vector<int32_t> source_to_target = nearest_descriptors(source, target, num_threads);
    const size_t n = source_to_target.size();
    CorrespondenceSet all(n);
    for (size_t i = 0; i < n; ++i) all[i] = Eigen::Vector2i(static_cast<int>(i), source_to_target[i]);
    if (!mutual_filter) return all;

    const std::vector<int32_t> target_to_source = nearest_descriptors(target, source, num_threads);
    CorrespondenceSet mutual;
    mutual.reserve(n);
    for (const Eigen::Vector2i& pair : all)
        if (target_to_source[static_cast<size_t>(pair(1))] == pair(0)) mutual.push_back(pair);
    // Open3D's rule: too few mutual pairs says the filter was too strict, so keep every pair.
    const auto enough = static_cast<size_t>(mutual_consistency_ratio * static_cast<double>(n));
    return mutual.size() >= enough ? mutual : all;
}

}  // namespace o3d::registration
