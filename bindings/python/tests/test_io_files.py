import pathlib

import numpy as np
import pytest

import o3d


@pytest.fixture
def colored(rng):
    pcd = o3d.geometry.PointCloud(rng.uniform(-5, 5, size=(50, 3)))
    n = rng.normal(size=(50, 3))
    pcd.normals = n / np.linalg.norm(n, axis=1, keepdims=True)
    pcd.colors = rng.integers(0, 256, size=(50, 3)) / 255.0
    return pcd


@pytest.mark.parametrize("ext,kw", [("ply", {}), ("pcd", {}), ("pcd", {"compressed": True})])
def test_binary_round_trip_is_exact(tmp_path, colored, ext, kw):
    path = tmp_path / f"cloud.{ext}"
    assert o3d.io.write_point_cloud(str(path), colored, **kw) is True
    back = o3d.io.read_point_cloud(str(path))
    # PLY keeps float64; PCD stores float32 (as Open3D writes it), so it is exact in float32.
    def stored(a):
        return a if ext == "ply" else a.astype(np.float32).astype(np.float64)
    np.testing.assert_array_equal(np.asarray(back.points), stored(np.asarray(colored.points)))
    np.testing.assert_array_equal(np.asarray(back.normals), stored(np.asarray(colored.normals)))
    np.testing.assert_allclose(np.asarray(back.colors), np.asarray(colored.colors), atol=1 / 255 / 2)


@pytest.mark.parametrize("ext", ["ply", "pcd"])
def test_ascii_round_trip(tmp_path, colored, ext):
    path = tmp_path / f"cloud.{ext}"
    o3d.io.write_point_cloud(path, colored, write_ascii=True)  # os.PathLike accepted
    assert path.read_bytes()[:200].isascii()
    back = o3d.io.read_point_cloud(path)
    np.testing.assert_allclose(np.asarray(back.points), np.asarray(colored.points), atol=1e-6)


@pytest.mark.parametrize("ext,has_normals,has_colors", [("xyz", False, False), ("xyzn", True, False),
                                                        ("xyzrgb", False, True), ("pts", False, True)])
def test_text_formats(tmp_path, colored, ext, has_normals, has_colors):
    path = tmp_path / f"cloud.{ext}"
    o3d.io.write_point_cloud(str(path), colored)
    back = o3d.io.read_point_cloud(str(path))
    assert len(back) == 50
    np.testing.assert_allclose(np.asarray(back.points), np.asarray(colored.points), atol=1e-6)
    assert back.has_normals() == has_normals
    assert back.has_colors() == has_colors
    if has_normals:
        np.testing.assert_allclose(np.asarray(back.normals), np.asarray(colored.normals), atol=1e-6)
    if has_colors:
        np.testing.assert_allclose(np.asarray(back.colors), np.asarray(colored.colors), atol=1 / 255)


def test_explicit_format_overrides_extension(tmp_path, colored):
    path = tmp_path / "cloud.bin"
    o3d.io.write_point_cloud(str(path), colored, format="ply")
    assert path.read_bytes().startswith(b"ply")
    assert len(o3d.io.read_point_cloud(str(path), format="ply")) == 50


def test_missing_file_raises_file_not_found(tmp_path):
    missing = tmp_path / "nope.pcd"
    with pytest.raises(FileNotFoundError) as info:
        o3d.io.read_point_cloud(str(missing))
    assert isinstance(info.value, o3d.O3DIOError) and isinstance(info.value, o3d.O3DError)
    assert info.value.status_name == "O3D_ERROR_IO"
    assert str(info.value)


def test_unwritable_path_raises_oserror(tmp_path, colored):
    with pytest.raises(OSError):
        o3d.io.write_point_cloud(str(tmp_path / "no" / "such" / "dir" / "a.ply"), colored)


def test_malformed_file_raises_parse_error(tmp_path):
    path = tmp_path / "bad.pcd"
    path.write_bytes(b"# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4\nGARBAGE\n")
    with pytest.raises(o3d.ParseError):
        o3d.io.read_point_cloud(str(path))


def test_unknown_format_raises(tmp_path, colored):
    with pytest.raises(o3d.O3DError):
        o3d.io.write_point_cloud(str(tmp_path / "a.unknownext"), colored)


def test_remove_nan_points_on_read(tmp_path):
    pcd = o3d.geometry.PointCloud(np.array([[0.0, 0, 0], [np.nan, 1, 1], [2, 2, 2]]))
    path = tmp_path / "nan.pcd"
    o3d.io.write_point_cloud(str(path), pcd)
    assert len(o3d.io.read_point_cloud(str(path))) == 3
    assert len(o3d.io.read_point_cloud(str(path), remove_nan_points=True)) == 2


def test_reads_open3d_fragment(data_file):
    pcd = o3d.io.read_point_cloud(data_file("open3d/fragment.pcd"))
    assert len(pcd) > 1000
    assert pcd.has_colors()
    assert np.all(np.isfinite(np.asarray(pcd.points)))
    assert pathlib.Path(data_file("open3d/fragment.pcd")).stat().st_size > 0
