// SPDX-License-Identifier: MIT
#pragma once
/// @file color_map.hpp
/// @brief o3d.pipelines.color_map: run_rigid_optimizer / run_non_rigid_optimizer with their (generated) options.
#include <vector>

#include "o3d/color_map.h"
#include "o3dpp/camera.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/rgbd.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

/// @brief What the optimizers return: Open3D's (mesh, trajectory) pair.
struct ColorMapResult {
    TriangleMesh mesh;             ///< a copy of the input mesh with the optimized vertex colours
    CameraTrajectory trajectory;   ///< the input trajectory with the refined extrinsics
};

namespace detail {
/// @brief One optimizer call: the images as C handles, the options' progress wired, both outputs owned.
template <typename Options, typename Run>
ColorMapResult run_color_map(Run run, const TriangleMesh& mesh, Span<const RgbdImage> images,
                             const CameraTrajectory& trajectory, const Options& options) {
    std::vector<const o3d_rgbd_image_t*> raw;
    for (const RgbdImage& image : images) raw.push_back(image.get());
    o3d_trianglemesh_t* out_mesh = nullptr;
    o3d_camera_trajectory_t* out_trajectory = nullptr;
    check(with_progress(options.to_c(), options.progress, [&](const auto* c) {
        return run(&out_mesh, &out_trajectory, mesh.get(), raw.data(), raw.size(), trajectory.get(), c);
    }));
    return {TriangleMesh(out_mesh), CameraTrajectory(out_trajectory)};
}
}  // namespace detail

/// @brief Refine each image's pose (images[i] was taken from the trajectory's pose i), then colour the mesh.
/// Colour is 8-bit RGB or float intensity, depth float metres, each the size its intrinsic says.
inline ColorMapResult run_rigid_optimizer(const TriangleMesh& mesh, Span<const RgbdImage> images,
                                          const CameraTrajectory& trajectory, const ColorMapRigidOptions& options = {}) {
    return detail::run_color_map(&o3d_color_map_run_rigid_optimizer, mesh, images, trajectory, options);
}
inline ColorMapResult run_rigid_optimizer(const TriangleMesh& mesh, const std::vector<RgbdImage>& images,
                                          const CameraTrajectory& trajectory, const ColorMapRigidOptions& options = {}) {
    return run_rigid_optimizer(mesh, Span<const RgbdImage>(images.data(), images.size()), trajectory, options);
}

/// @brief As run_rigid_optimizer, also refining a grid of anchor offsets that warps each image (not returned).
inline ColorMapResult run_non_rigid_optimizer(const TriangleMesh& mesh, Span<const RgbdImage> images,
                                              const CameraTrajectory& trajectory,
                                              const ColorMapNonRigidOptions& options = {}) {
    return detail::run_color_map(&o3d_color_map_run_non_rigid_optimizer, mesh, images, trajectory, options);
}
inline ColorMapResult run_non_rigid_optimizer(const TriangleMesh& mesh, const std::vector<RgbdImage>& images,
                                              const CameraTrajectory& trajectory,
                                              const ColorMapNonRigidOptions& options = {}) {
    return run_non_rigid_optimizer(mesh, Span<const RgbdImage>(images.data(), images.size()), trajectory, options);
}

}  // namespace o3dpp
