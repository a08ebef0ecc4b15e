// SPDX-License-Identifier: MIT
#pragma once
/// @file tsdf_volume.h
/// @brief Truncated signed distance volumes (Curless & Levoy 1996) as Open3D's legacy integration module
/// keeps them: depth frames averaged into voxels, the surface extracted by marching cubes.
#include <Eigen/Core>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/rgbd_image.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"
#include "o3d/integration/depth_tiles.h"
#include "o3d/integration/frame_integration.h"
#include "o3d/integration/voxel_block.h"

namespace o3d::integration {

/// @brief What colour each voxel keeps (Open3D's TSDFVolumeColorType): none, the frame's RGB8 colour, or
/// its float intensity (Gray32, kept as a grey colour).
enum class ColorType { None = 0, RGB8 = 1, Gray32 = 2 };

/// @brief What both volumes share: parameters, the voxel blocks, integration of one frame into chosen
/// blocks, and extraction. The frames are Open3D's integration input: depth 1-channel float metres
/// (RGBDImage from create_from_color_and_depth), colour 3-channel uint8 for RGB8, 1-channel float for Gray32.
class TSDFVolume {
public:
    virtual ~TSDFVolume() = default;
    double voxel_length() const { return voxel_length_; }
    double sdf_trunc() const { return sdf_trunc_; }
    ColorType color_type() const { return color_type_; }

    /// @brief Forget every frame.
    virtual void reset() = 0;
    /// @brief Fuse one frame seen by `intrinsic` from `extrinsic` (world to camera).
    /// @throws InvalidArgument on image formats the colour type cannot use, sizes other than the intrinsic's,
    /// an intrinsic with fx, fy <= 0, or a non-finite extrinsic. Nothing is changed then.
    virtual void integrate(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                           const Eigen::Matrix4d& extrinsic) = 0;

    /// @brief Marching cubes over every cube of 8 observed voxels: vertices on the zero crossings (with the
    /// interpolated colour unless the type is None), one per crossed edge, triangles wound toward free space.
    geometry::TriangleMesh extract_triangle_mesh() const;
    /// @brief The zero crossings between neighbouring observed voxels (|tsdf| < 0.98 on both), with normals
    /// from the tsdf's gradient and colours.
    geometry::PointCloud extract_point_cloud() const;
    /// @brief The centre of every observed, untruncated voxel (|tsdf| < 0.98), coloured grey by
    /// (tsdf + 1) / 2, as Open3D's debug view; voxels in grid order.
    geometry::PointCloud extract_voxel_point_cloud() const;
    /// @brief The same voxels as a VoxelGrid of edge voxel_length at the volume's origin (grid index: the voxel's
    /// index from that origin).
    geometry::VoxelGrid extract_voxel_grid() const;

protected:
    TSDFVolume(double voxel_length, double sdf_trunc, ColorType color_type, int block_side,
               const Eigen::Vector3d& origin);
    /// @brief Fuses a frame check_frame accepted into the blocks at `keys` (created when absent).
    void integrate_into(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                        const Eigen::Matrix4d& extrinsic, const std::vector<Eigen::Vector3i>& keys);
    /// @brief The checks integrate_into makes first; throws InvalidArgument.
    void check_frame(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                     const Eigen::Matrix4d& extrinsic) const;

    double voxel_length_;
    double sdf_trunc_;
    ColorType color_type_;
    detail::BlockMap blocks_;
    // Each column's and row's squared normalised ray coordinate (Open3D's depth-to-distance factor is
    // sqrt(1 + x^2 + y^2)), kept for the intrinsic they were made for.
    camera::PinholeCameraIntrinsic ray_intrinsic_;
    std::vector<float> ray_x2_, ray_y2_;
    // The frame being integrated, interleaved and summarised; kept so that each frame reuses their memory (a fresh
    // 5 MB buffer a frame costs more in page faults than filling it).
    std::vector<detail::FramePixel> frame_pixels_;
    detail::DepthTiles depth_tiles_;
};

}  // namespace o3d::integration
