"""RGBDImage and PointCloud.create_from_depth_image / create_from_rgbd_image: analytic back-projection,
Open3D 0.20 numbers on its RGB-D data (tools/reference/record_python_geometry.py), errors raise."""
import numpy as np
import pytest

import o3d

Image = o3d.geometry.Image
RGBD = o3d.geometry.RGBDImage
PC = o3d.geometry.PointCloud
K = o3d.camera.PinholeCameraIntrinsic


def synthetic_depth():
    """4x3 depth in mm: 1 m everywhere, one 0 (invalid) and one 5 m pixel."""
    d = np.full((3, 4), 1000, dtype=np.uint16)
    d[0, 0] = 0
    d[2, 3] = 5000
    return d


def test_create_from_color_and_depth_converts_depth_and_color():
    color = np.zeros((3, 4, 3), dtype=np.uint8)
    color[..., 0] = 255  # pure red
    rgbd = RGBD.create_from_color_and_depth(Image(color), Image(synthetic_depth()))
    depth = np.asarray(rgbd.depth)
    assert depth.dtype == np.float32
    expected = np.ones((3, 4), dtype=np.float32)
    expected[0, 0] = 0.0
    expected[2, 3] = 0.0  # beyond depth_trunc = 3 m
    np.testing.assert_allclose(depth, expected)
    intensity = np.asarray(rgbd.color)
    assert intensity.dtype == np.float32 and intensity.shape == (3, 4)
    np.testing.assert_allclose(intensity, 0.299, atol=1e-6)  # weighted gray of pure red
    kept = RGBD.create_from_color_and_depth(Image(color), Image(synthetic_depth()), depth_scale=1000.0,
                                            depth_trunc=10.0, convert_rgb_to_intensity=False)
    assert np.asarray(kept.color).shape == (3, 4, 3)
    assert np.asarray(kept.depth)[2, 3] == pytest.approx(5.0)
    with pytest.raises(ValueError):  # snapshots: writing them could never reach the C image
        np.asarray(rgbd.depth)[0, 0] = 1.0


def test_back_projection_is_analytic():
    intr = K(4, 3, 2.0, 2.0, 1.5, 1.0)
    pcd = PC.create_from_depth_image(Image(synthetic_depth()), intr, depth_trunc=3.0)
    pts = np.asarray(pcd.points)
    # valid pixels: all but (0,0) and the 5 m one, in row-major order, x = (u - cx) z / fx, y = (v - cy) z / fy
    expected = [((u - 1.5) / 2.0, (v - 1.0) / 2.0, 1.0) for v in range(3) for u in range(4)
                if (u, v) not in ((0, 0), (3, 2))]
    np.testing.assert_allclose(pts, expected)
    organised = PC.create_from_depth_image(Image(synthetic_depth()), intr, depth_trunc=3.0,
                                           project_valid_depth_only=False)
    assert len(organised.points) == 12 and np.isnan(np.asarray(organised.points)[0]).all()
    strided = PC.create_from_depth_image(Image(synthetic_depth()), intr, depth_trunc=3.0, stride=2)
    assert len(strided.points) == 3  # pixels (0,0) invalid, (2,0), (0,2), (2,2)
    # extrinsic is world-to-camera: a camera moved +1 in x sees the world shifted by -1
    E = np.eye(4)
    E[0, 3] = -1.0
    moved = PC.create_from_depth_image(Image(synthetic_depth()), intr, E, depth_trunc=3.0)
    np.testing.assert_allclose(np.asarray(moved.points), np.asarray(pcd.points) + [1.0, 0, 0])
    meters = PC.create_from_depth_image(Image(synthetic_depth().astype(np.float32) / 1000), intr, depth_scale=1.0,
                                        depth_trunc=3.0)
    np.testing.assert_allclose(np.asarray(meters.points), pts, atol=1e-6)


def test_rgbd_cloud_has_colors():
    color = np.zeros((3, 4, 3), dtype=np.uint8)
    color[..., 1] = 255
    rgbd = RGBD.create_from_color_and_depth(Image(color), Image(synthetic_depth()), convert_rgb_to_intensity=False)
    pcd = PC.create_from_rgbd_image(rgbd, K(4, 3, 2.0, 2.0, 1.5, 1.0))
    assert len(pcd.points) == 10 and pcd.has_colors()
    np.testing.assert_allclose(np.asarray(pcd.colors), np.tile([0, 1, 0], (10, 1)))


def test_open3d_frame_matches_open3d(data_file):
    color = o3d.io.read_image(data_file("open3d/RGBD/color/00000.jpg"))
    depth = o3d.io.read_image(data_file("open3d/RGBD/depth/00000.png"))
    rgbd = RGBD.create_from_color_and_depth(color, depth)
    assert float(np.asarray(rgbd.depth, dtype=np.float64).sum()) == pytest.approx(479199.33029168844, rel=1e-6)
    # JPEG decoders may differ by a level here and there: compare the mean loosely
    assert float(np.asarray(rgbd.color, dtype=np.float64).mean()) == pytest.approx(0.7713569729562247, abs=2e-3)
    intr = K(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    pcd = PC.create_from_rgbd_image(rgbd, intr)
    assert len(pcd.points) == 267129
    np.testing.assert_allclose(pcd.get_center(), [-0.04790395589573783, -0.05202429268729524, 1.793887336424306],
                               rtol=1e-6)
    np.testing.assert_allclose(np.asarray(pcd.colors).mean(axis=0), [0.7937774265857311] * 3, atol=2e-3)
    pd = PC.create_from_depth_image(depth, intr, depth_trunc=3.0, stride=2)
    assert len(pd.points) == 66782
    np.testing.assert_allclose(pd.get_center(), [-0.04948332648303465, -0.05360686549947622, 1.793901056147647],
                               rtol=1e-6)


def test_tum_format_matches_open3d(data_file):
    tum = RGBD.create_from_tum_format(o3d.io.read_image(data_file("open3d/RGBD/other_formats/TUM_color.png")),
                                      o3d.io.read_image(data_file("open3d/RGBD/other_formats/TUM_depth.png")))
    assert float(np.asarray(tum.depth, dtype=np.float64).sum()) == pytest.approx(585524.5596835613, rel=1e-6)


def test_other_dataset_formats_run(data_file):
    d = "open3d/RGBD/other_formats/"
    for make, c, z in [(RGBD.create_from_sun_format, "SUN_color.jpg", "SUN_depth.png"),
                       (RGBD.create_from_nyu_format, "NYU_color.ppm", "NYU_depth.pgm")]:
        rgbd = make(o3d.io.read_image(data_file(d + c)), o3d.io.read_image(data_file(d + z)))
        depth = np.asarray(rgbd.depth)
        assert depth.dtype == np.float32 and depth.max() <= 7.0 and depth.max() > 0.5
    red = RGBD.create_from_redwood_format(Image(np.zeros((3, 4, 3), np.uint8)), Image(synthetic_depth()))
    assert np.asarray(red.depth)[2, 3] == 0.0  # 5 m is past Redwood's 4 m truncation


def test_errors_raise():
    color = Image(np.zeros((3, 4, 3), dtype=np.uint8))
    with pytest.raises(ValueError):  # size mismatch
        RGBD.create_from_color_and_depth(color, Image(np.zeros((2, 2), dtype=np.uint16)))
    with pytest.raises(ValueError):  # color as depth
        RGBD.create_from_color_and_depth(color, color)
    with pytest.raises(ValueError):
        PC.create_from_depth_image(Image(synthetic_depth()), K(4, 3, 2, 2, 1.5, 1), stride=0)
    with pytest.raises(ValueError):
        PC.create_from_depth_image(Image(synthetic_depth()), K(4, 3, 2, 2, 1.5, 1), extrinsic=np.eye(3))
    with pytest.raises(ValueError):
        PC.create_from_rgbd_image(RGBD(), K(4, 3, 2, 2, 1.5, 1))
