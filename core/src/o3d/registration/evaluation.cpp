// SPDX-License-Identifier: MIT
#include "o3d/registration/evaluation.h"

#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/correspondence_pass.h"
#include "o3d/registration/validation.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {

RegistrationResult evaluate_registration(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                         double max_correspondence_distance, const Eigen::Matrix4d& transformation,
                                         int num_threads) {
    detail::check_registration_inputs(source, target, max_correspondence_distance, transformation, num_threads);
    const kdtree::KDTree tree(target.points);
    detail::PassWorkspace<detail::NoSums> ws;
    const auto totals = detail::correspondence_pass<detail::NoSums>(
        source.points, transformation, tree, max_correspondence_distance, utility::resolve_num_threads(num_threads),
        ws, [](detail::NoSums&, const Eigen::Vector3d&, int) {});
    RegistrationResult result;
    result.transformation = transformation;
    result.fitness = totals.fitness(source.size());
    result.inlier_rmse = totals.inlier_rmse();
    result.correspondence_set = detail::collect_correspondences(ws.nearest, totals.count);
    return result;
}

}  // namespace o3d::registration
