import pytest

import o3d


def test_hierarchy():
    assert issubclass(o3d.O3DError, RuntimeError)
    assert issubclass(o3d.InvalidArgumentError, ValueError)
    assert issubclass(o3d.O3DIOError, OSError)
    assert issubclass(o3d.O3DFileNotFoundError, FileNotFoundError)
    assert issubclass(o3d.O3DFileNotFoundError, o3d.O3DIOError)
    assert issubclass(o3d.UnsupportedError, NotImplementedError)
    for cls in (o3d.InvalidArgumentError, o3d.O3DMemoryError, o3d.O3DIOError, o3d.ParseError, o3d.UnsupportedError,
                o3d.NotConvergedError, o3d.CancelledError, o3d.InternalError):
        assert issubclass(cls, o3d.O3DError)


def test_library_error_carries_message_and_status():
    pcd = o3d.geometry.PointCloud([[0, 0, 0]])
    with pytest.raises(o3d.InvalidArgumentError) as info:
        pcd.voxel_down_sample(float("nan"))
    e = info.value
    assert e.status == -1 and e.status_name == "O3D_ERROR_INVALID_ARGUMENT"
    assert "voxel" in str(e).lower()


def test_error_state_is_cleared_after_raise():
    with pytest.raises(o3d.O3DError):
        o3d.geometry.PointCloud([[0, 0, 0]]).voxel_down_sample(-1.0)
    assert o3d._o3d._last_error() == (0, "")


def test_status_names():
    assert o3d._o3d._status_string(0) == "O3D_OK"
    assert o3d._o3d._status_string(-4) == "O3D_ERROR_PARSE"


def test_wrong_argument_types_raise_type_error():
    with pytest.raises(TypeError):
        o3d.geometry.PointCloud().voxel_down_sample("big")
    with pytest.raises(TypeError):
        o3d.io.write_point_cloud("x.ply", "not a cloud")
