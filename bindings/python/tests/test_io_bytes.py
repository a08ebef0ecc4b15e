import numpy as np
import pytest

import o3d


@pytest.mark.parametrize("fmt", ["ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts"])
def test_bytes_round_trip(fmt, random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    pcd.normals = np.tile([0.0, 0.0, 1.0], (500, 1))
    pcd.colors = np.tile([0.2, 0.4, 0.6], (500, 1))
    data = o3d.io.write_point_cloud_to_bytes(pcd, fmt)
    assert isinstance(data, bytes) and len(data) > 0
    back = o3d.io.read_point_cloud_from_bytes(data, fmt)
    np.testing.assert_allclose(np.asarray(back.points), random_points, atol=1e-6)


def test_xyzrgb_without_colors_raises(random_points):
    # Open3D's writer returns False here; o3d raises instead of failing silently.
    with pytest.raises(ValueError):
        o3d.io.write_point_cloud_to_bytes(o3d.geometry.PointCloud(random_points), "xyzrgb")


def test_binary_pcd_bytes_are_exact_and_ascii_is_text(random_points):
    # PCD stores coordinates as float32 (as Open3D writes it), so the round trip is exact in float32.
    as_f32 = random_points.astype(np.float32).astype(np.float64)
    pcd = o3d.geometry.PointCloud(random_points)
    data = o3d.io.write_point_cloud_to_bytes(pcd, "pcd")
    np.testing.assert_array_equal(np.asarray(o3d.io.read_point_cloud_from_bytes(data, "pcd").points), as_f32)
    text = o3d.io.write_point_cloud_to_bytes(pcd, "ply", write_ascii=True)
    assert text.startswith(b"ply") and b"ascii" in text[:100]
    compressed = o3d.io.write_point_cloud_to_bytes(pcd, "pcd", compressed=True)
    assert b"binary_compressed" in compressed[:400]
    back = o3d.io.read_point_cloud_from_bytes(bytearray(compressed), "pcd")
    np.testing.assert_array_equal(np.asarray(back.points), as_f32)


def test_zero_copy_buffer_matches_bytes(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    buf = o3d.io.write_point_cloud_to_buffer(pcd, "ply")
    assert buf.dtype == np.uint8 and not buf.flags.writeable and not buf.flags.owndata
    assert buf.tobytes() == o3d.io.write_point_cloud_to_bytes(pcd, "ply")
    back = o3d.io.read_point_cloud_from_bytes(memoryview(buf), "ply")
    assert len(back) == 500


@pytest.mark.parametrize("fmt,data", [
    ("pcd", b"this is not a pcd file"),
    ("ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\nend_header\n\x00\x01"),
    ("ply", b""),
    ("xyz", b"1 2 3\n4 5 oops\n"),
])
def test_malformed_bytes_raise_parse_error(fmt, data):
    with pytest.raises(o3d.ParseError) as info:
        o3d.io.read_point_cloud_from_bytes(data, fmt)
    assert info.value.status_name == "O3D_ERROR_PARSE"
    assert str(info.value)


def test_unknown_format_in_memory():
    with pytest.raises(o3d.UnsupportedError):
        o3d.io.read_point_cloud_from_bytes(b"1 2 3\n", "obj-nope")
