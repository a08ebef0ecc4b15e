"""o3d.pipelines.integration. Reference numbers recorded from the open3d 0.20 wheel (tools/reference/record_tsdf.py)
on its rgbd_integration tutorial frames: its UniformTSDFVolume(4.0, 512, origin (-3.5, -1.5, 0.5)), on the same
voxel grid as a scalable volume, gives 147927 vertices, 280605 triangles and 141105 points, mean colour
(0.8439, 0.7838, 0.7514); its ScalableTSDFVolume gives an empty mesh there."""
import numpy as np
import pytest

import o3d

integration = o3d.pipelines.integration
SMALL = o3d.camera.PinholeCameraIntrinsic(160, 120, 100.0, 100.0, 79.5, 59.5)


def _plane_frame(z=1.0, rgb=True):
    depth = np.full((120, 160), z, dtype=np.float32)
    color = np.zeros((120, 160, 3), dtype=np.uint8)
    color[:] = (200, 100, 50)
    return o3d.geometry.RGBDImage.create_from_color_and_depth(
        o3d.geometry.Image(color), o3d.geometry.Image(depth), depth_scale=1.0, convert_rgb_to_intensity=not rgb)


def test_plane_comes_back_at_its_depth():
    # Exact projective distances: the zero crossing is the plane, one vertex per voxel column of the 64^3 cube.
    volume = integration.UniformTSDFVolume(length=1.0, resolution=64, sdf_trunc=0.04,
                                           color_type=integration.TSDFVolumeColorType.RGB8, origin=[-0.5, -0.5, 0.5])
    volume.integrate(_plane_frame(), SMALL, np.identity(4))
    mesh = volume.extract_triangle_mesh()
    vertices = np.asarray(mesh.vertices)
    assert vertices.shape == (64 * 64, 3)
    assert len(mesh.triangles) == 2 * 63 * 63
    np.testing.assert_allclose(vertices[:, 2], 1.0, atol=1e-4)
    np.testing.assert_allclose(np.asarray(mesh.vertex_colors), np.tile([200 / 255, 100 / 255, 50 / 255], (64 * 64, 1)),
                               atol=1e-5)
    # A voxel in front of the plane holds its distance over sdf_trunc; one frame gives weight 1.
    tsdf = volume.extract_volume_tsdf()
    assert tsdf.shape == (64 ** 3, 2) and tsdf.dtype == np.float32
    z = 0.5 + 30.5 / 64
    assert tsdf[(32 * 64 + 32) * 64 + 30, 0] == pytest.approx((1.0 - z) / 0.04, abs=1e-4)
    assert tsdf[(32 * 64 + 32) * 64 + 30, 1] == 1.0
    assert volume.extract_volume_color().shape == (64 ** 3, 3)
    assert (volume.length, volume.resolution) == (1.0, 64)
    np.testing.assert_array_equal(volume.origin, [-0.5, -0.5, 0.5])
    assert volume.voxel_length == 1.0 / 64 and volume.sdf_trunc == 0.04
    assert volume.color_type == integration.TSDFVolumeColorType.RGB8
    # Points on the plane with normals toward the camera (free space).
    cloud = volume.extract_point_cloud()
    normals = np.asarray(cloud.normals)
    assert len(cloud.points) == 64 * 64
    assert np.all(normals[:, 2] < -0.99)
    grid = volume.extract_voxel_grid()
    assert len(grid.get_voxels()) == len(volume.extract_voxel_point_cloud().points) > 0
    volume.reset()
    assert len(volume.extract_triangle_mesh().vertices) == 0


def test_scalable_and_uniform_agree_and_scalable_keeps_only_the_surface():
    scalable = integration.ScalableTSDFVolume(voxel_length=1.0 / 64, sdf_trunc=0.04,
                                              color_type=integration.TSDFVolumeColorType.NoColor)
    uniform = integration.UniformTSDFVolume(1.0, 64, 0.04, integration.TSDFVolumeColorType.NoColor, [-0.5, -0.5, 0.5])
    for v in (scalable, uniform):
        v.integrate(_plane_frame(), SMALL, np.identity(4))
    a, b = uniform.extract_triangle_mesh(), scalable.extract_triangle_mesh()
    assert not b.has_vertex_colors()
    # The scalable volume sees the whole frustum's plane, a superset of the cube's 64 x 64 columns.
    inside = np.asarray(b.vertices)
    inside = inside[np.all(np.abs(inside[:, :2]) < 0.5, axis=1)]
    assert len(inside) == len(a.vertices)
    np.testing.assert_allclose(np.sort(inside[:, 0]), np.sort(np.asarray(a.vertices)[:, 0]), atol=1e-6)
    assert (scalable.volume_unit_resolution, scalable.depth_sampling_stride) == (16, 4)


def test_tutorial_frames_match_open3d(data_file):
    # Open3D's rgbd_integration tutorial, as written for Open3D (import open3d as o3d).
    trajectory = o3d.io.read_pinhole_camera_trajectory(data_file("open3d/RGBD/trajectory.log"))
    volume = integration.ScalableTSDFVolume(voxel_length=4.0 / 512.0, sdf_trunc=0.04,
                                            color_type=integration.TSDFVolumeColorType.RGB8)
    for i, camera in enumerate(trajectory.parameters):
        color = o3d.io.read_image(data_file(f"open3d/RGBD/color/{i:05d}.jpg"))
        depth = o3d.io.read_image(data_file(f"open3d/RGBD/depth/{i:05d}.png"))
        rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth, depth_trunc=4.0,
                                                                  convert_rgb_to_intensity=False)
        volume.integrate(rgbd, camera.intrinsic, camera.extrinsic)
    mesh = volume.extract_triangle_mesh()
    assert len(mesh.vertices) == pytest.approx(147927, rel=0.002)
    assert len(mesh.triangles) == pytest.approx(280605, rel=0.002)
    np.testing.assert_allclose(np.asarray(mesh.vertex_colors).mean(axis=0), [0.8439, 0.7838, 0.7514], atol=2e-3)
    assert len(volume.extract_point_cloud().points) == pytest.approx(141105, rel=0.002)


def test_bad_input_raises():
    volume = integration.ScalableTSDFVolume(0.01, 0.04, integration.TSDFVolumeColorType.RGB8)
    with pytest.raises(ValueError, match="RGB8"):
        volume.integrate(_plane_frame(rgb=False), SMALL, np.identity(4))
    with pytest.raises(ValueError):
        volume.integrate(_plane_frame(), o3d.camera.PinholeCameraIntrinsic(320, 240, 100.0, 100.0, 159.5, 119.5),
                         np.identity(4))
    bad = np.identity(4)
    bad[0, 3] = np.nan
    with pytest.raises(ValueError):
        volume.integrate(_plane_frame(), SMALL, bad)
    with pytest.raises(ValueError):
        integration.ScalableTSDFVolume(-1.0, 0.04, integration.TSDFVolumeColorType.NoColor)
    with pytest.raises(ValueError):
        integration.UniformTSDFVolume(1.0, 0, 0.04, integration.TSDFVolumeColorType.NoColor)
    assert len(volume.extract_triangle_mesh().vertices) == 0  # nothing was fused
