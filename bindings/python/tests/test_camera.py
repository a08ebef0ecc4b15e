"""o3d.camera (PinholeCameraIntrinsic, PinholeCameraParameters, PinholeCameraTrajectory) and their o3d.io
readers/writers. Open3D numbers: tools/reference/record_python_geometry.py."""
import copy

import numpy as np
import pytest

import o3d

cam = o3d.camera


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def test_intrinsic_constructors():
    ps = cam.PinholeCameraIntrinsic(cam.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    assert (ps.width, ps.height) == (640, 480)
    assert ps.get_focal_length() == (525.0, 525.0) and ps.get_principal_point() == (319.5, 239.5)
    np.testing.assert_array_equal(ps.intrinsic_matrix, [[525, 0, 319.5], [0, 525, 239.5], [0, 0, 1]])
    k2 = cam.PinholeCameraIntrinsic(cam.PinholeCameraIntrinsicParameters.Kinect2DepthCameraDefault)
    assert (k2.width, k2.height) == (512, 424) and k2.get_focal_length() == (365.456, 365.456)
    k2c = cam.PinholeCameraIntrinsic(cam.PinholeCameraIntrinsicParameters.Kinect2ColorCameraDefault)
    assert (k2c.width, k2c.height) == (1920, 1080)
    a = cam.PinholeCameraIntrinsic(320, 240, 300.0, 310.0, 160.0, 120.0)
    b = cam.PinholeCameraIntrinsic(width=320, height=240, intrinsic_matrix=a.intrinsic_matrix)
    assert a == b and a.is_valid()
    c = cam.PinholeCameraIntrinsic(a)
    c.set_intrinsics(10, 20, 1.0, 2.0, 3.0, 4.0)
    assert (c.width, c.height, c.get_focal_length(), c.get_principal_point()) == (10, 20, (1.0, 2.0), (3.0, 4.0))
    assert a.width == 320  # the copy is independent
    d = cam.PinholeCameraIntrinsic()
    assert (d.width, d.height) == (-1, -1) and not d.is_valid()
    d.intrinsic_matrix = [[5, 0, 1], [0, 6, 2], [0, 0, 1]]
    assert d.get_focal_length() == (5.0, 6.0)
    e = copy.deepcopy(a)
    assert e == a and "width = 320" in repr(e)
    with pytest.raises(ValueError):
        d.intrinsic_matrix = np.eye(4)


def test_parameters_and_trajectory():
    p = cam.PinholeCameraParameters()
    np.testing.assert_array_equal(p.extrinsic, np.eye(4))
    p.extrinsic[0, 3] = 2.0  # a view, as Open3D's Eigen member
    assert p.extrinsic[0, 3] == 2.0
    p.intrinsic = cam.PinholeCameraIntrinsic(cam.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    p.intrinsic.width = 100  # reference to the member, as Open3D's def_readwrite
    assert p.intrinsic.width == 100
    traj = cam.PinholeCameraTrajectory()
    assert traj.parameters == []
    q = cam.PinholeCameraParameters(p)
    q.extrinsic = np.diag([1.0, 1.0, 1.0, 1.0])
    traj.parameters = [p, q]
    got = traj.parameters
    assert len(got) == 2 and got[0].intrinsic.width == 100
    np.testing.assert_array_equal(got[0].extrinsic, p.extrinsic)
    np.testing.assert_array_equal(got[1].extrinsic, np.eye(4))
    bad = cam.PinholeCameraParameters()
    bad.extrinsic[3, 0] = 1.0
    with pytest.raises(ValueError):
        traj.parameters = [bad]
    with pytest.raises(TypeError):
        traj.parameters = [1]
    assert len(traj.parameters) == 2  # a rejected assignment changes nothing
    copy_traj = cam.PinholeCameraTrajectory(traj)
    assert len(copy_traj.parameters) == len(traj.parameters) == len(copy_traj) == 2
    copy_traj.parameters = []
    assert copy_traj.parameters == [] and len(traj.parameters) == 2


def test_io_roundtrips(tmp_path):
    k = cam.PinholeCameraIntrinsic(320, 240, 300.0, 310.0, 160.0, 120.0)
    assert o3d.io.write_pinhole_camera_intrinsic(str(tmp_path / "k.json"), k)
    assert o3d.io.read_pinhole_camera_intrinsic(str(tmp_path / "k.json")) == k
    p = cam.PinholeCameraParameters()
    p.intrinsic = k
    p.extrinsic = np.array([[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]], dtype=np.float64)
    o3d.io.write_pinhole_camera_parameters(str(tmp_path / "p.json"), p)
    back = o3d.io.read_pinhole_camera_parameters(str(tmp_path / "p.json"))
    assert back.intrinsic == k
    np.testing.assert_allclose(back.extrinsic, p.extrinsic)
    traj = cam.PinholeCameraTrajectory()
    traj.parameters = [p, p]
    for ext in ("json", "log"):
        path = str(tmp_path / f"t.{ext}")
        o3d.io.write_pinhole_camera_trajectory(path, traj)
        got = o3d.io.read_pinhole_camera_trajectory(path)
        assert len(got.parameters) == 2
        np.testing.assert_allclose(got.parameters[1].extrinsic, p.extrinsic, atol=1e-12)


def test_open3d_files(data_file):
    k = o3d.io.read_pinhole_camera_intrinsic(data_file("open3d/camera_primesense.json"))
    assert (k.width, k.height, k.get_focal_length(), k.get_principal_point()) == (640, 480, (525.0, 525.0),
                                                                                  (319.5, 239.5))
    traj = o3d.io.read_pinhole_camera_trajectory(data_file("open3d/camera_trajectory.json"))
    assert len(traj.parameters) == 31
    assert fp(traj.parameters[0].extrinsic) == pytest.approx(27.541413870283318, rel=1e-12)
    log = o3d.io.read_pinhole_camera_trajectory(data_file("open3d/RGBD/trajectory.log"))
    assert len(log.parameters) == 5
    assert fp(log.parameters[0].extrinsic) == pytest.approx(3.206951756851071, rel=1e-9)


def test_io_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        o3d.io.read_pinhole_camera_intrinsic(str(tmp_path / "none.json"))
    bad = tmp_path / "bad.json"
    bad.write_text("{ not json")
    with pytest.raises(o3d.O3DError):
        o3d.io.read_pinhole_camera_intrinsic(str(bad))
    with pytest.raises(o3d.O3DError):
        o3d.io.read_pinhole_camera_trajectory(str(bad))
    with pytest.raises(o3d.O3DError):
        o3d.io.read_pinhole_camera_parameters(str(bad))
