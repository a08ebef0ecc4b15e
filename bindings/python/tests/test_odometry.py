"""o3d.pipelines.odometry. Reference numbers recorded from the open3d 0.20 wheel on its RGBD test frames 0 -> 1
(default OdometryOption, PrimeSense intrinsics): hybrid term t = (-0.0010704978, 0.0232280983, 0.0014059205)
with 252387 correspondences on the information diagonal; color term t = (0.0002740545, 0.0229634918,
0.0006021213) with 251852."""
import numpy as np
import pytest

import o3d

odometry = o3d.pipelines.odometry


def _synthetic_frame():
    u, v = np.meshgrid(np.arange(160), np.arange(120))
    color = (0.5 + 0.2 * np.sin(0.3 * u) * np.cos(0.25 * v) + 0.1 * np.sin(0.11 * (u + v))).astype(np.float32)
    depth = (1.5 + 0.004 * u + 0.002 * v).astype(np.float32)
    return o3d.geometry.RGBDImage.create_from_color_and_depth(o3d.geometry.Image(color), o3d.geometry.Image(depth),
                                                              depth_scale=1.0)


SMALL = o3d.camera.PinholeCameraIntrinsic(160, 120, 130.0, 130.0, 79.5, 59.5)


def test_option_defaults_and_fields():
    o = odometry.OdometryOption()
    assert list(o.iteration_number_per_pyramid_level) == [20, 10, 5]
    assert (o.depth_diff_max, o.depth_min, o.depth_max) == (0.03, 0.0, 4.0)
    o.iteration_number_per_pyramid_level = o3d.utility.IntVector([4, 2])
    o.depth_max = 3.0
    assert list(o.iteration_number_per_pyramid_level) == [4, 2] and o.depth_max == 3.0
    with pytest.raises(ValueError):
        odometry.OdometryOption(iteration_number_per_pyramid_level=[])


@pytest.mark.parametrize("jacobian", [odometry.RGBDOdometryJacobianFromColorTerm(),
                                      odometry.RGBDOdometryJacobianFromHybridTerm()])
def test_a_frame_onto_itself_is_the_identity(jacobian):
    frame = _synthetic_frame()
    ok, trans, info = odometry.compute_rgbd_odometry(frame, frame, SMALL, np.identity(4), jacobian,
                                                     odometry.OdometryOption())
    assert ok
    np.testing.assert_allclose(trans, np.identity(4), atol=1e-12)
    assert info.shape == (6, 6) and info[3, 3] > 0.9 * 160 * 120


def test_open3d_frames_zero_to_one(data_file):
    def frame(i):
        color = o3d.io.read_image(data_file(f"open3d/RGBD/color/{i:05d}.jpg"))
        depth = o3d.io.read_image(data_file(f"open3d/RGBD/depth/{i:05d}.png"))
        return o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth)

    source, target = frame(0), frame(1)
    intrinsic = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    ok, trans, info = odometry.compute_rgbd_odometry(source, target, intrinsic, np.identity(4),
                                                     odometry.RGBDOdometryJacobianFromHybridTerm(),
                                                     odometry.OdometryOption())
    assert ok
    np.testing.assert_allclose(trans[:3, 3], [-0.0010704978, 0.0232280983, 0.0014059205], atol=1e-5)
    assert info[3, 3] == pytest.approx(252387, rel=1e-3)
    ok, trans, _ = odometry.compute_rgbd_odometry(source, target, intrinsic)  # Open3D's defaults: the color term
    assert ok
    np.testing.assert_allclose(trans[:3, 3], [0.0002740545, 0.0229634918, 0.0006021213], atol=5e-4)


def test_errors_and_no_overlap():
    frame = _synthetic_frame()
    with pytest.raises(ValueError):
        odometry.compute_rgbd_odometry(frame, frame, o3d.camera.PinholeCameraIntrinsic(640, 480, 500, 500, 320, 240))
    with pytest.raises(ValueError):
        odometry.compute_rgbd_odometry(frame, frame, SMALL, np.full((4, 4), np.nan))
    rgb = o3d.geometry.RGBDImage.create_from_color_and_depth(
        o3d.geometry.Image(np.zeros((120, 160, 3), np.uint8)), o3d.geometry.Image(np.ones((120, 160), np.float32)),
        depth_scale=1.0, convert_rgb_to_intensity=False)
    with pytest.raises(ValueError):
        odometry.compute_rgbd_odometry(rgb, frame, SMALL)
    near = odometry.OdometryOption(depth_max=0.5)
    ok, trans, info = odometry.compute_rgbd_odometry(frame, frame, SMALL, option=near)
    assert not ok
    np.testing.assert_array_equal(trans, np.identity(4))
