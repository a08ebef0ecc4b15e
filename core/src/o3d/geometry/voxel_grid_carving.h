// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_grid_carving.h
/// @brief Space carving of a voxel grid with a depth map or a silhouette seen by a pinhole camera
/// (Open3D's VoxelGrid.carve_depth_map and carve_silhouette).
#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/image.h"
#include "o3d/geometry/voxel_grid.h"

namespace o3d::geometry {

/// @brief Remove the voxels the depth map shows to be empty space (Open3D's carve_depth_map).
///
/// Each of a voxel's 8 corners (voxel_bounding_points) is taken to the camera, x_c = R x + t with
/// [R | t] = params.extrinsic (world to camera), and projected: u = (fx x_c + cx z) / z, v = (fy y_c + cy z)
/// / z with z = x_c's third coordinate. The corner is inside the image when z > 0 and u in [0, width - 1],
/// v in [0, height - 1] (pixel centres at integers, as Open3D's Image.FloatValueAt); there the depth d is
/// the bilinear interpolation of the 4 surrounding pixels. A voxel is kept when at least one corner is
/// inside the image with d > 0 and z >= d (on or behind the observed surface), or when
/// `keep_voxels_outside_image` and at least one corner is outside the image; otherwise it is removed.
/// A NaN or infinite depth pixel is no measurement (its interpolations are not > 0 or never reached).
///
/// `depth` must be one channel of float32 depths in the units of the extrinsic (metres): Open3D 0.20 reads
/// no other format (a uint16 or uint8 image is "outside the image" at every pixel there), so any other
/// format throws here. Differences from Open3D 0.20: a corner with z <= 0 (at or behind the camera) counts
/// as outside the image (Open3D divides by z regardless). `num_threads`: 0 = the library default; the
/// result does not depend on it. Throws InvalidArgument for an image that is not 1-channel float32, empty,
/// whose data size is not width x height x 4 bytes, or whose size differs from the intrinsic's; for
/// non-finite intrinsics or zero focal lengths; for an extrinsic that is not a rigid motion (finite, last row
/// (0, 0, 0, 1), a rotation block); for a grid whose voxel_size is not finite and > 0 or whose origin is not finite.
void carve_depth_map(VoxelGrid& grid, const Image& depth, const camera::PinholeCameraParameters& params,
                     bool keep_voxels_outside_image = false, int num_threads = 0);

/// @brief Remove the voxels that project entirely outside the silhouette (Open3D's carve_silhouette).
///
/// Corners are projected as in carve_depth_map. A voxel is kept when at least one corner is inside the
/// image and the bilinearly interpolated mask value there is > 0, or when `keep_voxels_outside_image` and
/// at least one corner is outside the image; otherwise it is removed. `mask` must be one channel of
/// float32 (0 = background, > 0 = object), the only format Open3D 0.20 reads (it treats every pixel of a
/// uint8 or uint16 mask as outside the image). Throws InvalidArgument as carve_depth_map.
void carve_silhouette(VoxelGrid& grid, const Image& mask, const camera::PinholeCameraParameters& params,
                      bool keep_voxels_outside_image = false, int num_threads = 0);

}  // namespace o3d::geometry
