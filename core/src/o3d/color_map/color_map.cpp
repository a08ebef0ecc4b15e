// SPDX-License-Identifier: MIT
// The driver of both optimizers: prepare the images, decide visibility once, then alternate (a) one
// Gauss-Newton step per image on its pose (and warp) with the vertex intensities fixed and (b) the vertex
// intensities as the mean of the images at the new poses (Zhou & Koltun 2014, section 5: alternating
// optimization). Finally colour the mesh from the images at the refined poses.
#include "o3d/color_map/color_map.h"

#include <cmath>
#include <string>
#include <utility>

#include "o3d/color_map/pose_step.h"
#include "o3d/color_map/vertex_colors.h"
#include "o3d/color_map/view_images.h"
#include "o3d/color_map/visibility.h"
#include "o3d/utility/error.h"
#include "o3d/utility/logging.h"
#include "o3d/utility/parallel.h"

namespace o3d::color_map {

namespace {

using detail::View;

/// Everything but the pose steps is shared: `vertical_anchors` 0 means rigid.
ColorMapResult optimize(const geometry::TriangleMesh& mesh, const std::vector<const geometry::RGBDImage*>& images,
                        const camera::PinholeCameraTrajectory& trajectory, const OptimizerOption& option,
                        int vertical_anchors, double anchor_weight) {
    detail::check_inputs(mesh, images, trajectory, option);
    const int threads = utility::resolve_num_threads(option.num_threads);
    const int num_views = int(images.size());

    detail::Scene scene;
    scene.vertices = &mesh.vertices;
    scene.images.resize(images.size());
    scene.visible.resize(images.size());
    std::vector<View> views(images.size());
    for (size_t c = 0; c < images.size(); ++c) {
        views[c].intrinsic = trajectory.parameters[c].intrinsic;
        views[c].extrinsic = trajectory.parameters[c].extrinsic;
        if (vertical_anchors > 0)
            views[c].warp = detail::WarpingField(images[c]->depth.width, images[c]->depth.height, vertical_anchors);
    }
    // Each image on its own: the per-image work is independent and writes only its own slot.
#pragma omp parallel for schedule(dynamic) num_threads(threads) if (threads > 1)
    for (int c = 0; c < num_views; ++c) {
        scene.images[size_t(c)] = detail::prepare_view_images(*images[size_t(c)], option);
        scene.visible[size_t(c)] =
            detail::visible_vertices(mesh.vertices, views[size_t(c)], scene.images[size_t(c)], option);
    }
    scene.vertex_views = detail::invert_visibility(scene.visible, mesh.vertices.size());

    std::vector<double> proxy(mesh.vertices.size(), 0.0);
    detail::update_proxy_intensity(proxy, scene, views, threads);
    std::vector<detail::StepStatistics> stats(images.size());
    std::vector<double> residuals;
    for (int it = 0; it < option.maximum_iteration; ++it) {
#pragma omp parallel for schedule(dynamic) num_threads(threads) if (threads > 1)
        for (int c = 0; c < num_views; ++c)
            stats[size_t(c)] = detail::gauss_newton_step(views[size_t(c)], scene.images[size_t(c)],
                                                         scene.visible[size_t(c)], mesh.vertices, proxy,
                                                         anchor_weight);
        detail::update_proxy_intensity(proxy, scene, views, threads);
        double error = 0.0;
        long count = 0;
        for (const auto& st : stats) {  // in image order: the same sum for any thread count
            error += st.squared_error;
            count += st.residuals;
        }
        residuals.push_back(count ? error / double(count) : 0.0);
        if (utility::log_enabled(utility::LogLevel::Debug))
            utility::log_debug("color map iteration " + std::to_string(it + 1) + ": mean squared residual " +
                               std::to_string(residuals.back()) + " over " + std::to_string(count) + " residuals");
        if (option.progress && !option.progress(double(it + 1) / option.maximum_iteration))
            throw Cancelled("color map optimization cancelled by the progress callback after iteration " +
                            std::to_string(it + 1));
    }

    ColorMapResult out;
    out.mesh = mesh;
    out.mesh.vertex_colors = detail::vertex_colors(scene, views, option.invisible_vertex_color_knn, threads);
    out.residuals = std::move(residuals);
    out.trajectory = trajectory;
    for (size_t c = 0; c < views.size(); ++c) out.trajectory.parameters[c].extrinsic = views[c].extrinsic;
    return out;
}

std::vector<const geometry::RGBDImage*> pointers(const std::vector<geometry::RGBDImage>& images) {
    std::vector<const geometry::RGBDImage*> out;
    out.reserve(images.size());
    for (const auto& im : images) out.push_back(&im);
    return out;
}

void check_non_rigid(const NonRigidOptimizerOption& option) {
    if (option.number_of_vertical_anchors < 2)
        throw InvalidArgument("number_of_vertical_anchors must be >= 2, got " +
                              std::to_string(option.number_of_vertical_anchors));
    if (!(option.non_rigid_anchor_point_weight >= 0.0) || !std::isfinite(option.non_rigid_anchor_point_weight))
        throw InvalidArgument("non_rigid_anchor_point_weight must be finite and >= 0, got " +
                              std::to_string(option.non_rigid_anchor_point_weight));
}

}  // namespace

ColorMapResult run_rigid_optimizer(const geometry::TriangleMesh& mesh,
                                   const std::vector<const geometry::RGBDImage*>& images,
                                   const camera::PinholeCameraTrajectory& camera_trajectory,
                                   const RigidOptimizerOption& option) {
    return optimize(mesh, images, camera_trajectory, option, 0, 0.0);
}

ColorMapResult run_rigid_optimizer(const geometry::TriangleMesh& mesh, const std::vector<geometry::RGBDImage>& images,
                                   const camera::PinholeCameraTrajectory& camera_trajectory,
                                   const RigidOptimizerOption& option) {
    return run_rigid_optimizer(mesh, pointers(images), camera_trajectory, option);
}

ColorMapResult run_non_rigid_optimizer(const geometry::TriangleMesh& mesh,
                                       const std::vector<const geometry::RGBDImage*>& images,
                                       const camera::PinholeCameraTrajectory& camera_trajectory,
                                       const NonRigidOptimizerOption& option) {
    check_non_rigid(option);
    return optimize(mesh, images, camera_trajectory, option, option.number_of_vertical_anchors,
                    option.non_rigid_anchor_point_weight);
}

ColorMapResult run_non_rigid_optimizer(const geometry::TriangleMesh& mesh,
                                       const std::vector<geometry::RGBDImage>& images,
                                       const camera::PinholeCameraTrajectory& camera_trajectory,
                                       const NonRigidOptimizerOption& option) {
    return run_non_rigid_optimizer(mesh, pointers(images), camera_trajectory, option);
}

}  // namespace o3d::color_map
