// SPDX-License-Identifier: MIT
#include "o3d/registration/icp.h"

#include <cmath>
#include <string>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/correspondence_pass.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/estimation_point_to_point.h"
#include "o3d/registration/validation.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

void check_options(const IcpOptions& options) {
    const auto& c = options.criteria;
    if (c.max_iteration < 0)
        throw InvalidArgument("max_iteration must be >= 0, got " + std::to_string(c.max_iteration));
    if (!(c.relative_fitness >= 0.0)) throw InvalidArgument("relative_fitness must be >= 0 (and not NaN)");
    if (!(c.relative_rmse >= 0.0)) throw InvalidArgument("relative_rmse must be >= 0 (and not NaN)");
}

/// The loop of Open3D's RegistrationICP. One pass both scores the current transformation and
/// gathers the sums the next update is solved from, so each iteration costs a single sweep.
template <typename Sums, typename Visit, typename Solve>
RegistrationResult run_icp(const geometry::PointCloud& source, const kdtree::KDTree& tree, double max_distance,
                           const Eigen::Matrix4d& init, const IcpOptions& options, const Visit& visit,
                           const Solve& solve) {
    const int threads = utility::resolve_num_threads(options.num_threads);
    const auto& criteria = options.criteria;
    detail::PassWorkspace<Sums> ws;
    Eigen::Matrix4d transformation = init;
    auto totals = detail::correspondence_pass<Sums>(source.points, transformation, tree, max_distance, threads, ws, visit);
    double fitness = totals.fitness(source.size());
    double rmse = totals.inlier_rmse();
    for (int i = 0; i < criteria.max_iteration; ++i) {
        transformation = solve(totals.sums) * transformation;
        const double previous_fitness = fitness;
        const double previous_rmse = rmse;
        totals = detail::correspondence_pass<Sums>(source.points, transformation, tree, max_distance, threads, ws, visit);
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

}  // namespace

RegistrationResult registration_icp(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                    double max_correspondence_distance, const Eigen::Matrix4d& init,
                                    const IcpOptions& options) {
    detail::check_registration_inputs(source, target, max_correspondence_distance, init, options.num_threads);
    check_options(options);
    if (options.estimation == Estimation::PointToPlane && !target.has_normals())
        throw InvalidArgument("point-to-plane ICP needs target normals");

    const kdtree::KDTree tree(target.points);
    if (options.estimation == Estimation::PointToPlane) {
        const auto& points = target.points;
        const auto& normals = target.normals;
        const auto visit = [&](detail::PointToPlaneSums& sums, const Eigen::Vector3d& moved, int index) {
            // A pair with a broken normal still counts in fitness/RMSE but cannot constrain the plane.
            if (normals[index].allFinite()) sums.accumulate(moved, points[index], normals[index]);
        };
        return run_icp<detail::PointToPlaneSums>(source, tree, max_correspondence_distance, init, options, visit,
                                                 detail::solve_point_to_plane);
    }
    // Moments are taken about the target centroid: the moved source lies near it, so the sums stay small.
    const Eigen::Vector3d reference = centroid(target.points);
    const auto& points = target.points;
    const auto visit = [&](detail::PointToPointSums& sums, const Eigen::Vector3d& moved, int index) {
        sums.accumulate(moved - reference, points[index] - reference);
    };
    const bool with_scaling = options.with_scaling;
    const auto solve = [&](const detail::PointToPointSums& sums) {
        return detail::solve_point_to_point(sums, reference, with_scaling);
    };
    return run_icp<detail::PointToPointSums>(source, tree, max_correspondence_distance, init, options, visit, solve);
}

}  // namespace o3d::registration
