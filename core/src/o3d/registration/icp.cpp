// SPDX-License-Identifier: MIT
#include "o3d/registration/icp.h"

#include <cmath>
#include <string>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/correspondence_pass.h"
#include "o3d/registration/estimation_colored.h"
#include "o3d/registration/estimation_generalized.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/estimation_point_to_point.h"
#include "o3d/registration/estimation_symmetric.h"
#include "o3d/registration/validation.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

void check_options(const IcpOptions& options) {
    const auto& c = options.criteria;
    const int estimation = static_cast<int>(options.estimation);
    if (estimation < static_cast<int>(Estimation::PointToPoint) || estimation > static_cast<int>(Estimation::Symmetric))
        throw InvalidArgument("unknown estimation " + std::to_string(estimation));
    if (c.max_iteration < 0)
        throw InvalidArgument("max_iteration must be >= 0, got " + std::to_string(c.max_iteration));
    if (!(c.relative_fitness >= 0.0)) throw InvalidArgument("relative_fitness must be >= 0 (and not NaN)");
    if (!(c.relative_rmse >= 0.0)) throw InvalidArgument("relative_rmse must be >= 0 (and not NaN)");
    check_robust_kernel(options.kernel);
    detail::check_lambda_geometric(options.lambda_geometric);
    detail::check_epsilon(options.epsilon);
}

void check_attributes(const IcpOptions& options, const geometry::PointCloud& source,
                      const geometry::PointCloud& target) {
    switch (options.estimation) {
        case Estimation::PointToPlane:
            if (!target.has_normals()) throw InvalidArgument("point-to-plane ICP needs target normals");
            break;
        case Estimation::Colored:
            if (!source.has_colors()) throw InvalidArgument("colored ICP needs source colors");
            if (!target.has_colors()) throw InvalidArgument("colored ICP needs target colors");
            if (!target.has_normals()) throw InvalidArgument("colored ICP needs target normals");
            break;
        case Estimation::Symmetric:
            if (!source.has_normals()) throw InvalidArgument("symmetric ICP needs source normals");
            if (!target.has_normals()) throw InvalidArgument("symmetric ICP needs target normals");
            break;
        default:
            break;
    }
}

/// The loop of Open3D's RegistrationICP. One pass both scores the current transformation and
/// gathers the sums the next update is solved from, so each iteration costs a single sweep.
/// `make_visit(transformation)` gives the pair visitor of a pass at that transformation.
template <typename Sums, typename MakeVisit, typename Solve>
RegistrationResult run_icp(const geometry::PointCloud& source, const kdtree::KDTree& tree, double max_distance,
                           const Eigen::Matrix4d& init, const IcpOptions& options, const MakeVisit& make_visit,
                           const Solve& solve) {
    const int threads = utility::resolve_num_threads(options.num_threads);
    const auto& criteria = options.criteria;
    detail::PassWorkspace<Sums> ws;
    const auto pass = [&](const Eigen::Matrix4d& t) {
        return detail::correspondence_pass<Sums>(source.points, t, tree, max_distance, threads, ws, make_visit(t));
    };
    Eigen::Matrix4d transformation = init;
    auto totals = pass(transformation);
    double fitness = totals.fitness(source.size());
    double rmse = totals.inlier_rmse();
    for (int i = 0; i < criteria.max_iteration; ++i) {
        transformation = solve(totals.sums) * transformation;
        const double previous_fitness = fitness;
        const double previous_rmse = rmse;
        totals = pass(transformation);
        fitness = totals.fitness(source.size());
        rmse = totals.inlier_rmse();
        if (options.progress && !options.progress(static_cast<double>(i + 1) / criteria.max_iteration))
            throw Cancelled("ICP cancelled by the progress callback after iteration " + std::to_string(i + 1));
        if (std::abs(previous_fitness - fitness) < criteria.relative_fitness &&
            std::abs(previous_rmse - rmse) < criteria.relative_rmse)
            break;
    }
    RegistrationResult result;
    result.transformation = transformation;
    result.fitness = fitness;
    result.inlier_rmse = rmse;
    result.correspondence_set = detail::collect_correspondences(ws.nearest, totals.count);
    return result;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : points) sum += p;
    return sum / static_cast<double>(points.size());
}

Eigen::Matrix3d rotation_of(const Eigen::Matrix4d& t) { return t.topLeftCorner<3, 3>(); }

RegistrationResult point_to_point(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                  const kdtree::KDTree& tree, double max_distance, const Eigen::Matrix4d& init,
                                  const IcpOptions& options) {
    // Moments are taken about the target centroid: the moved source lies near it, so the sums stay small.
    const Eigen::Vector3d reference = centroid(target.points);
    const auto& points = target.points;
    const auto make_visit = [&](const Eigen::Matrix4d&) {
        return [&](detail::PointToPointSums& sums, const Eigen::Vector3d& moved, int index) {
            sums.accumulate(moved - reference, points[index] - reference);
        };
    };
    const bool with_scaling = options.with_scaling;
    const auto solve = [&](const detail::PointToPointSums& sums) {
        return detail::solve_point_to_point(sums, reference, with_scaling);
    };
    return run_icp<detail::PointToPointSums>(source, tree, max_distance, init, options, make_visit, solve);
}

RegistrationResult point_to_plane(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                  const kdtree::KDTree& tree, double max_distance, const Eigen::Matrix4d& init,
                                  const IcpOptions& options) {
    const auto& points = target.points;
    const auto& normals = target.normals;
    const RobustKernel kernel = options.kernel;
    const auto make_visit = [&](const Eigen::Matrix4d&) {
        return [&](detail::PointToPlaneSums& sums, const Eigen::Vector3d& moved, int index) {
            // A pair with a broken normal still counts in fitness/RMSE but cannot constrain the plane.
            if (normals[index].allFinite()) sums.accumulate(moved, points[index], normals[index], kernel);
        };
    };
    return run_icp<detail::PointToPlaneSums>(source, tree, max_distance, init, options, make_visit,
                                             detail::solve_point_to_plane);
}

RegistrationResult colored(const geometry::PointCloud& source, const geometry::PointCloud& target,
                           const kdtree::KDTree& tree, double max_distance, const Eigen::Matrix4d& init,
                           const IcpOptions& options) {
    // Open3D's registration_colored_icp: gradients over twice the correspondence distance, 30 neighbours.
    const std::vector<Eigen::Vector3d> gradients =
        compute_color_gradients(target, tree, 2.0 * max_distance, 30, options.num_threads);
    const std::vector<double> source_intensity = color_intensities(source.colors);
    const std::vector<double> target_intensity = color_intensities(target.colors);
    const auto& points = target.points;
    const auto& normals = target.normals;
    const detail::ColoredRows rows(options.lambda_geometric);
    const RobustKernel kernel = options.kernel;
    const auto make_visit = [&](const Eigen::Matrix4d&) {
        return [&](detail::ColoredSums& sums, const Eigen::Vector3d& moved, int index, int64_t i) {
            const double is = source_intensity[static_cast<size_t>(i)];
            if (!normals[index].allFinite() || !std::isfinite(is) || !std::isfinite(target_intensity[index])) return;
            sums.accumulate(rows, moved, is, points[index], normals[index], gradients[index], target_intensity[index],
                            kernel);
        };
    };
    return run_icp<detail::ColoredSums>(source, tree, max_distance, init, options, make_visit,
                                        detail::solve_point_to_plane);
}

RegistrationResult generalized(const geometry::PointCloud& source, const geometry::PointCloud& target,
                               const kdtree::KDTree& tree, double max_distance, const Eigen::Matrix4d& init,
                               const IcpOptions& options) {
    const std::vector<Eigen::Matrix3d> source_cov =
        generalized_icp_covariances(source, options.epsilon, options.num_threads);
    const std::vector<Eigen::Matrix3d> target_cov =
        generalized_icp_covariances(target, options.epsilon, options.num_threads, &tree);
    const auto& points = target.points;
    const RobustKernel kernel = options.kernel;
    const auto make_visit = [&](const Eigen::Matrix4d& t) {
        // The source covariances turn with the source: C = R C_s R^T + C_q.
        return [&, r = rotation_of(t)](detail::GeneralizedSums& sums, const Eigen::Vector3d& moved, int index,
                                       int64_t i) {
            const Eigen::Matrix3d c = r * source_cov[static_cast<size_t>(i)] * r.transpose() + target_cov[index];
            sums.accumulate(moved, moved - points[index], c, kernel);
        };
    };
    return run_icp<detail::GeneralizedSums>(source, tree, max_distance, init, options, make_visit,
                                            detail::solve_point_to_plane);
}

RegistrationResult symmetric(const geometry::PointCloud& source, const geometry::PointCloud& target,
                             const kdtree::KDTree& tree, double max_distance, const Eigen::Matrix4d& init,
                             const IcpOptions& options) {
    const Eigen::Vector3d reference = centroid(target.points);
    const auto& points = target.points;
    const auto& normals = target.normals;
    const auto& source_normals = source.normals;
    const RobustKernel kernel = options.kernel;
    const auto make_visit = [&](const Eigen::Matrix4d& t) {
        return [&, r = rotation_of(t)](detail::SymmetricSums& sums, const Eigen::Vector3d& moved, int index,
                                       int64_t i) {
            const Eigen::Vector3d n =
                detail::symmetric_normal(r * source_normals[static_cast<size_t>(i)], normals[index]);
            if (n.allFinite()) sums.accumulate(moved - reference, points[index] - reference, n, kernel);
        };
    };
    const auto solve = [&](const detail::SymmetricSums& sums) { return detail::solve_symmetric(sums, reference); };
    return run_icp<detail::SymmetricSums>(source, tree, max_distance, init, options, make_visit, solve);
}

}  // namespace

RegistrationResult registration_icp(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                    double max_correspondence_distance, const Eigen::Matrix4d& init,
                                    const IcpOptions& options) {
    detail::check_registration_inputs(source, target, max_correspondence_distance, init, options.num_threads);
    check_options(options);
    check_attributes(options, source, target);

    const kdtree::KDTree tree(target.points);
    const double d = max_correspondence_distance;
    switch (options.estimation) {
        case Estimation::PointToPlane:
            return point_to_plane(source, target, tree, d, init, options);
        case Estimation::Colored:
            return colored(source, target, tree, d, init, options);
        case Estimation::Generalized:
            return generalized(source, target, tree, d, init, options);
        case Estimation::Symmetric:
            return symmetric(source, target, tree, d, init, options);
        case Estimation::PointToPoint:
            break;
    }
    return point_to_point(source, target, tree, d, init, options);
}

}  // namespace o3d::registration
