"""o3d.io.read_image / write_image (files and bytes): round trips, Open3D's data, errors raise."""
import numpy as np
import pytest

import o3d

Image = o3d.geometry.Image


@pytest.mark.parametrize("ext,array", [
    ("png", np.arange(60, dtype=np.uint8).reshape(5, 4, 3)),
    ("png", (np.arange(20, dtype=np.uint16) * 3000).reshape(4, 5)),
    ("png", np.arange(80, dtype=np.uint8).reshape(4, 5, 4)),
    ("ppm", np.arange(60, dtype=np.uint8).reshape(5, 4, 3)),
    ("pgm", (np.arange(20, dtype=np.uint16) * 3000).reshape(4, 5)),
    ("pgm", np.arange(20, dtype=np.uint8).reshape(4, 5)),
])
def test_lossless_roundtrip(tmp_path, ext, array):
    path = tmp_path / f"img.{ext}"
    assert o3d.io.write_image(str(path), Image(array))
    back = o3d.io.read_image(path)  # os.PathLike accepted
    np.testing.assert_array_equal(np.asarray(back), array)
    data = o3d.io.write_image_to_bytes(Image(array), ext)
    np.testing.assert_array_equal(np.asarray(o3d.io.read_image_from_bytes(data, ext)), array)


def test_jpeg_quality(tmp_path):
    y, x = np.mgrid[0:32, 0:32]
    a = np.stack([x * 8, y * 8, (x + y) * 4], axis=-1).astype(np.uint8)  # smooth: JPEG keeps it closely
    hi = o3d.io.write_image_to_bytes(Image(a), "jpg", quality=95)
    lo = o3d.io.write_image_to_bytes(Image(a), "jpg", quality=10)
    assert len(lo) < len(hi)
    o3d.io.write_image(str(tmp_path / "a.jpg"), Image(a), quality=90)
    back = np.asarray(o3d.io.read_image(str(tmp_path / "a.jpg"))).astype(np.int32)
    assert back.shape == a.shape and np.abs(back - a).mean() < 3


def test_open3d_depth_png(data_file):
    depth = o3d.io.read_image(data_file("open3d/RGBD/depth/00000.png"))
    arr = np.asarray(depth)
    assert arr.shape == (480, 640) and arr.dtype == np.uint16
    flat = arr.astype(np.float64).ravel()
    # Open3D 0.20 (tools/reference/record_python_geometry.py): fp = 68929080641606.0
    assert float(((np.arange(flat.size) + 1) * flat).sum()) == 68929080641606.0
    color = o3d.io.read_image(data_file("open3d/RGBD/color/00000.jpg"))
    assert np.asarray(color).shape == (480, 640, 3)


def test_errors_raise(tmp_path):
    with pytest.raises(FileNotFoundError):
        o3d.io.read_image(str(tmp_path / "missing.png"))
    bad = tmp_path / "bad.png"
    bad.write_bytes(b"\x89PNG\r\n\x1a\nnot really")
    with pytest.raises(o3d.O3DError):
        o3d.io.read_image(str(bad))
    with pytest.raises(o3d.O3DError):  # float images are not written
        o3d.io.write_image(str(tmp_path / "f.png"), Image(np.zeros((2, 2), dtype=np.float32)))
    with pytest.raises(NotImplementedError):
        o3d.io.write_image(str(tmp_path / "x.bmp"), Image(np.zeros((2, 2), dtype=np.uint8)))
    with pytest.raises(o3d.O3DError):
        o3d.io.read_image_from_bytes(b"", "png")
