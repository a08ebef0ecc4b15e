// SPDX-License-Identifier: MIT
// C API of colour-map optimization (color_map.h).
#include "o3d/color_map.h"

#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/color_map/color_map.h"

namespace {

namespace cm = o3d::color_map;

constexpr o3d_color_map_rigid_options_t kRigidDefaults = {
    sizeof(o3d_color_map_rigid_options_t), 300, 2.5, 0.03, 0.1, 3, 10, 3, 0, nullptr, nullptr};
constexpr o3d_color_map_non_rigid_options_t kNonRigidDefaults = {
    sizeof(o3d_color_map_non_rigid_options_t), 16, 0.316, 300, 2.5, 0.03, 0.1, 3, 10, 3, 0, nullptr, nullptr};

/// The fields both C structs share, into the core's shared options (the core validates the values).
template <typename C>
void to_core(const C& o, cm::OptimizerOption& out) {
    out.maximum_iteration = o.maximum_iteration;
    out.maximum_allowable_depth = o.maximum_allowable_depth;
    out.depth_threshold_for_visibility_check = o.depth_threshold_for_visibility_check;
    out.depth_threshold_for_discontinuity_check = o.depth_threshold_for_discontinuity_check;
    out.half_dilation_kernel_size_for_discontinuity_map = o.half_dilation_kernel_size_for_discontinuity_map;
    out.image_boundary_margin = o.image_boundary_margin;
    out.invisible_vertex_color_knn = o.invisible_vertex_color_knn;
    out.num_threads = o.num_threads;
    out.progress = o3d::capi::to_progress(o.progress, o.user_data);
}

/// The images the handles hold, borrowed for the call (no copy).
std::vector<const o3d::geometry::RGBDImage*> gather_images(const o3d_rgbd_image_t* const* images, size_t num_images) {
    o3d::capi::require(images, "images");
    std::vector<const o3d::geometry::RGBDImage*> out;
    out.reserve(num_images);
    for (size_t i = 0; i < num_images; ++i) {
        if (!images[i]) throw o3d::InvalidArgument("images[" + std::to_string(i) + "] is NULL");
        out.push_back(&images[i]->rgbd);
    }
    return out;
}

/// Shared body: check the pointers, run, and only then hand out both handles (never half of them).
template <typename Run>
void run(o3d_trianglemesh_t** out_colored_mesh, o3d_camera_trajectory_t** out_refined_trajectory, const o3d_trianglemesh_t* mesh,
         const o3d_rgbd_image_t* const* images, size_t num_images, const o3d_camera_trajectory_t* trajectory,
         Run&& optimize) {
    using o3d::capi::require;
    require(out_colored_mesh, "out_colored_mesh");
    require(out_refined_trajectory, "out_refined_trajectory");
    *out_colored_mesh = nullptr;
    *out_refined_trajectory = nullptr;
    require(mesh, "mesh");
    require(trajectory, "trajectory");
    if (num_images != trajectory->trajectory.parameters.size())
        throw o3d::InvalidArgument(std::to_string(num_images) + " RGB-D images but the trajectory has " +
                                   std::to_string(trajectory->trajectory.parameters.size()) +
                                   " poses; they must pair up");
    const std::vector<const o3d::geometry::RGBDImage*> rgbd = gather_images(images, num_images);
    cm::ColorMapResult result = optimize(mesh->mesh, rgbd, trajectory->trajectory);
    auto m = std::make_unique<o3d_trianglemesh>();
    auto t = std::make_unique<o3d_camera_trajectory>();
    m->mesh = std::move(result.mesh);
    t->trajectory = std::move(result.trajectory);
    *out_colored_mesh = m.release();
    *out_refined_trajectory = t.release();
}

}  // namespace

O3D_API o3d_status o3d_color_map_rigid_options_init(o3d_color_map_rigid_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kRigidDefaults, "opts"); });
}

O3D_API o3d_status o3d_color_map_non_rigid_options_init(o3d_color_map_non_rigid_options_t* opts,
                                                        uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kNonRigidDefaults, "opts"); });
}

O3D_API o3d_status o3d_color_map_run_rigid_optimizer(o3d_trianglemesh_t** out_colored_mesh,
                                                     o3d_camera_trajectory_t** out_refined_trajectory,
                                                     const o3d_trianglemesh_t* mesh,
                                                     const o3d_rgbd_image_t* const* images, size_t num_images,
                                                     const o3d_camera_trajectory_t* trajectory,
                                                     const o3d_color_map_rigid_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        run(out_colored_mesh, out_refined_trajectory, mesh, images, num_images, trajectory,
            [&](const auto& m, const auto& rgbd, const auto& traj) {
                cm::RigidOptimizerOption option;
                to_core(o3d::capi::read_options(opts, kRigidDefaults, "opts"), option);
                return cm::run_rigid_optimizer(m, rgbd, traj, option);
            });
    });
}

O3D_API o3d_status o3d_color_map_run_non_rigid_optimizer(o3d_trianglemesh_t** out_colored_mesh,
                                                         o3d_camera_trajectory_t** out_refined_trajectory,
                                                         const o3d_trianglemesh_t* mesh,
                                                         const o3d_rgbd_image_t* const* images, size_t num_images,
                                                         const o3d_camera_trajectory_t* trajectory,
                                                         const o3d_color_map_non_rigid_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        run(out_colored_mesh, out_refined_trajectory, mesh, images, num_images, trajectory,
            [&](const auto& m, const auto& rgbd, const auto& traj) {
                const o3d_color_map_non_rigid_options_t o = o3d::capi::read_options(opts, kNonRigidDefaults, "opts");
                cm::NonRigidOptimizerOption option;
                to_core(o, option);
                option.number_of_vertical_anchors = o.number_of_vertical_anchors;
                option.non_rigid_anchor_point_weight = o.non_rigid_anchor_point_weight;
                return cm::run_non_rigid_optimizer(m, rgbd, traj, option);
            });
    });
}
