import pytest

import o3d
from o3d.utility import VerbosityLevel


def test_verbosity_round_trip():
    old = o3d.utility.get_verbosity_level()
    try:
        for level in VerbosityLevel:
            o3d.utility.set_verbosity_level(level)
            assert o3d.utility.get_verbosity_level() == level
    finally:
        o3d.utility.set_verbosity_level(old)


def test_verbosity_default_is_warning_and_levels_match_c():
    assert [int(v) for v in (VerbosityLevel.Error, VerbosityLevel.Warning, VerbosityLevel.Info,
                             VerbosityLevel.Debug)] == [0, 1, 2, 3]


def test_bad_verbosity_raises_value_error():
    with pytest.raises(ValueError):
        o3d.utility.set_verbosity_level(7)


def test_verbosity_context_manager_restores():
    o3d.utility.set_verbosity_level(VerbosityLevel.Warning)
    with o3d.utility.VerbosityContextManager(VerbosityLevel.Debug):
        assert o3d.utility.get_verbosity_level() == VerbosityLevel.Debug
    assert o3d.utility.get_verbosity_level() == VerbosityLevel.Warning


def test_log_callback_rejects_non_callable():
    with pytest.raises(TypeError):
        o3d.utility.set_log_callback(42)


def test_log_callback_receives_library_messages(tmp_path):
    # A missing file at Debug verbosity is the most likely call to log; skip if the library logs nothing.
    seen = []
    old = o3d.utility.get_verbosity_level()
    o3d.utility.set_log_callback(lambda level, msg: seen.append((level, msg)))
    try:
        o3d.utility.set_verbosity_level(VerbosityLevel.Debug)
        pcd = o3d.geometry.PointCloud([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]])
        pcd.estimate_normals()
        o3d.io.write_point_cloud(str(tmp_path / "a.ply"), pcd)
        o3d.io.read_point_cloud(str(tmp_path / "a.ply"))
    finally:
        o3d.utility.set_log_callback(None)
        o3d.utility.set_verbosity_level(old)
    if not seen:
        pytest.skip("the library logged nothing at Debug level for these calls")
    assert all(isinstance(level, VerbosityLevel) and isinstance(msg, str) for level, msg in seen)


def test_num_threads_round_trip():
    old = o3d.utility.get_num_threads()
    try:
        o3d.utility.set_num_threads(1)
        assert o3d.utility.get_num_threads() == 1
        o3d.utility.set_num_threads(0)
        assert o3d.utility.get_num_threads() >= 1
    finally:
        o3d.utility.set_num_threads(0)
    assert old >= 1


def test_negative_num_threads_raises():
    with pytest.raises(ValueError):
        o3d.utility.set_num_threads(-2)
