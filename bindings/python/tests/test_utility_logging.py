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
    c = o3d._o3d  # the members are the C O3D_LOG_* constants, exported by the extension
    assert [c.O3D_LOG_ERROR, c.O3D_LOG_WARNING, c.O3D_LOG_INFO, c.O3D_LOG_DEBUG] == [0, 1, 2, 3]


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
    # Every failure is logged at Debug level, so a failed read at Debug verbosity must reach the callback.
    seen = []
    old = o3d.utility.get_verbosity_level()
    o3d.utility.set_log_callback(lambda level, msg: seen.append((level, msg)))
    missing = str(tmp_path / "missing.ply")
    try:
        o3d.utility.set_verbosity_level(VerbosityLevel.Debug)
        with pytest.raises(OSError):
            o3d.io.read_point_cloud(missing)
        o3d.utility.set_verbosity_level(VerbosityLevel.Warning)
        with pytest.raises(OSError):
            o3d.io.read_point_cloud(str(tmp_path / "second.ply"))
    finally:
        o3d.utility.set_log_callback(None)
        o3d.utility.set_verbosity_level(old)
    assert [level for level, _ in seen] == [VerbosityLevel.Debug]
    assert "missing.ply" in seen[0][1]


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
