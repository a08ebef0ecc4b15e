// SPDX-License-Identifier: MIT
#pragma once
/// @file color_map.h
/// @brief Colour-map optimization (Open3D's o3d.pipelines.color_map; Zhou & Koltun, "Color Map Optimization for
/// 3D Reconstruction with Consumer Depth Cameras", SIGGRAPH 2014): refine the camera poses of the RGB-D images a
/// mesh was reconstructed from so that the images agree on the colour of every vertex, then colour the mesh.
#include <functional>
#include <vector>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/rgbd_image.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::color_map {

/// @brief The options both optimizers share, with Open3D's (C++) defaults.
struct OptimizerOption {
    int maximum_iteration = 300;  ///< alternations of pose update and vertex-intensity update
    /// Metres: an image pixel deeper than this does not see the vertex projected onto it (drops the background).
    double maximum_allowable_depth = 2.5;
    /// Metres: a vertex is seen only when its depth in the camera and the depth image's differ by at most this.
    double depth_threshold_for_visibility_check = 0.03;
    /// Pixels whose depth Sobel magnitude (Open3D's unscaled 3x3 filter) exceeds this are depth discontinuities.
    double depth_threshold_for_discontinuity_check = 0.1;
    /// Pixels within this many pixels (square window) of a discontinuity see nothing: depth is unreliable there.
    int half_dilation_kernel_size_for_discontinuity_map = 3;
    int image_boundary_margin = 10;      ///< pixels: vertices projected this close to the border are not seen
    int invisible_vertex_color_knn = 3;  ///< a vertex no image sees gets the mean colour of this many seen ones
    int num_threads = 0;                 ///< 0 = library default
    /// Called on the calling thread after each iteration with (iteration + 1) / maximum_iteration.
    /// Returning false cancels the call (o3d::Cancelled).
    std::function<bool(double)> progress;
};

/// @brief RigidOptimizerOption: only the 6-DoF pose of every image moves.
struct RigidOptimizerOption : OptimizerOption {};

/// @brief NonRigidOptimizerOption: every image also gets a grid of anchor points whose 2-D offsets (pixels),
/// interpolated bilinearly, warp where the vertices land in it (lens distortion, rolling shutter, small
/// geometric errors of the mesh).
struct NonRigidOptimizerOption : OptimizerOption {
    /// Anchors along the image height (>= 2); along the width as many as keep the same spacing.
    int number_of_vertical_anchors = 16;
    /// lambda of the regulariser lambda^2 * sum ||offset||^2 (offsets in pixels, intensities in [0, 1]): the
    /// larger, the closer the warp stays to none.
    double non_rigid_anchor_point_weight = 0.316;
};

/// @brief What both optimizers return: the mesh with the optimized vertex colours, and the refined trajectory
/// (Open3D's pair), plus how the optimizer's own objective went.
struct ColorMapResult {
    geometry::TriangleMesh mesh;
    camera::PinholeCameraTrajectory trajectory;
    /// Per iteration, the mean squared photometric residual (intensity in [0, 1]) over the vertices the images see,
    /// at the poses (and warps) the iteration starts from.
    std::vector<double> residuals;
};

/// @brief run_rigid_optimizer. `images[i]` was taken by `camera_trajectory.parameters[i]` (extrinsic:
/// world to camera). Each image's colour is 8-bit RGB (or 8-bit gray, or a 1-channel float intensity in
/// [0, 1]), its depth 1-channel float metres, both the size its intrinsic says. Only the vertices are used.
/// Results are bitwise identical for any thread count.
/// @throws o3d::InvalidArgument on a mesh without vertices or with a non-finite one, no images, a count of
/// images other than the trajectory's, an image of another format or size, a bad intrinsic or extrinsic, or a
/// bad option. @throws o3d::Cancelled when `progress` returns false.
ColorMapResult run_rigid_optimizer(const geometry::TriangleMesh& mesh, const std::vector<geometry::RGBDImage>& images,
                                   const camera::PinholeCameraTrajectory& camera_trajectory,
                                   const RigidOptimizerOption& option = {});

/// @brief As above, over images the caller keeps (none may be null): what the C API uses, so that it need not
/// copy them.
ColorMapResult run_rigid_optimizer(const geometry::TriangleMesh& mesh,
                                   const std::vector<const geometry::RGBDImage*>& images,
                                   const camera::PinholeCameraTrajectory& camera_trajectory,
                                   const RigidOptimizerOption& option = {});

/// @brief run_non_rigid_optimizer: as run_rigid_optimizer, and each image's anchor grid is optimized with its
/// pose. The returned trajectory holds the poses only (the warps are not returned, as in Open3D).
/// @throws as run_rigid_optimizer, and on number_of_vertical_anchors < 2 or a negative or NaN anchor weight.
ColorMapResult run_non_rigid_optimizer(const geometry::TriangleMesh& mesh,
                                       const std::vector<geometry::RGBDImage>& images,
                                       const camera::PinholeCameraTrajectory& camera_trajectory,
                                       const NonRigidOptimizerOption& option = {});
/// @brief As above, over images the caller keeps (none may be null).
ColorMapResult run_non_rigid_optimizer(const geometry::TriangleMesh& mesh,
                                       const std::vector<const geometry::RGBDImage*>& images,
                                       const camera::PinholeCameraTrajectory& camera_trajectory,
                                       const NonRigidOptimizerOption& option = {});

}  // namespace o3d::color_map
