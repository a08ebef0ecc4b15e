"""o3d.geometry.Image: numpy in and out (zero-copy), filters, pyramids, flips, conversions, errors.

Reference numbers: tools/reference/record_python_geometry.py (Open3D 0.20.0).
"""
import copy
import gc
import pickle

import numpy as np
import pytest

import o3d

Image = o3d.geometry.Image


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


@pytest.mark.parametrize("dtype,shape", [(np.uint8, (4, 5)), (np.uint8, (4, 5, 3)), (np.uint16, (3, 2)),
                                         (np.float32, (2, 3, 4)), (np.uint8, (3, 4, 1))])
def test_numpy_roundtrip_and_attributes(dtype, shape):
    a = (np.arange(np.prod(shape)) % 200).astype(dtype).reshape(shape)
    img = Image(a)
    out = np.asarray(img)
    expected_shape = shape if (len(shape) == 3 and shape[2] > 1) else shape[:2]
    assert out.shape == expected_shape and out.dtype == dtype
    np.testing.assert_array_equal(out, a.reshape(expected_shape))
    assert (img.height, img.width) == shape[:2]
    assert img.num_of_channels == (shape[2] if len(shape) == 3 else 1) == img.channels
    assert img.bytes_per_channel == np.dtype(dtype).itemsize
    assert "Image of size" in repr(img)


def test_view_is_zero_copy_and_writes_through():
    img = Image(np.zeros((3, 4), dtype=np.uint8))
    v = np.asarray(img)
    assert v.flags.writeable and np.shares_memory(v, np.asarray(img))
    v[0, :] = 7  # seen by the library: the flipped copy has it in the last row
    np.testing.assert_array_equal(np.asarray(img.flip_vertical())[2], [7, 7, 7, 7])
    assert img._data_copy()[:4] == bytes([7] * 4)
    del img
    gc.collect()
    assert v[0, 0] == 7  # the view keeps the image alive


def test_non_contiguous_input_is_copied_correctly():
    a = np.arange(48, dtype=np.uint8).reshape(6, 8)[::2, ::2]
    np.testing.assert_array_equal(np.asarray(Image(a)), a)


def test_flips():
    a = np.arange(24, dtype=np.uint16).reshape(4, 6)
    img = Image(a)
    np.testing.assert_array_equal(np.asarray(img.flip_vertical()), np.flipud(a))
    np.testing.assert_array_equal(np.asarray(img.flip_horizontal()), np.fliplr(a))
    c = np.arange(36, dtype=np.uint8).reshape(3, 4, 3)
    np.testing.assert_array_equal(np.asarray(Image(c).flip_horizontal()), c[:, ::-1, :])


def test_filters_match_open3d():
    f = (np.sin(np.arange(30, dtype=np.float32)).reshape(5, 6) + 1.0).astype(np.float32)
    img = Image(f)
    ref = {"Gaussian3": 476.09980472922325, "Gaussian5": 468.9541945159435, "Gaussian7": 453.04598993062973,
           "Sobel3dx": -287.66449868679047, "Sobel3dy": 58.24880492687225}
    for name, value in ref.items():
        out = img.filter(getattr(o3d.geometry.ImageFilterType, name))
        assert np.asarray(out).shape == (5, 6) and np.asarray(out).dtype == np.float32
        assert fp(out) == pytest.approx(value, rel=1e-5, abs=1e-3), name
    assert Image.FilterType.Gaussian3 == o3d.geometry.ImageFilterType.Gaussian3
    levels = Image.filter_pyramid([img, img], o3d.geometry.ImageFilterType.Gaussian3)
    assert len(levels) == 2 and fp(levels[1]) == pytest.approx(ref["Gaussian3"], rel=1e-5)


def test_filter_requires_float_single_channel():
    with pytest.raises(ValueError):
        Image(np.zeros((4, 4), dtype=np.uint8)).filter(o3d.geometry.ImageFilterType.Gaussian3)


@pytest.mark.parametrize("gaussian,fps", [
    (True, [-20432.851035670246, -1192.6383391553536, -63.953404404222965]),
    (False, [-20432.851035670246, -1193.021094294265, -64.09148128703237]),
])
def test_pyramid_matches_open3d(gaussian, fps):
    big = Image(np.cos(np.arange(64 * 48, dtype=np.float32) * 0.1).reshape(48, 64).astype(np.float32))
    pyr = big.create_pyramid(3, gaussian)
    assert [np.asarray(p).shape for p in pyr] == [(48, 64), (24, 32), (12, 16)]
    for level, value in zip(pyr, fps):
        assert fp(level) == pytest.approx(value, rel=1e-5, abs=1e-3)
    with pytest.raises(ValueError):
        Image(np.zeros((4, 4), dtype=np.uint8)).create_pyramid(2, True)


def test_float_conversions():
    rgb = np.array([[[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]]], dtype=np.uint8)
    w = np.asarray(Image(rgb).create_float_image())  # default Weighted, as Open3D's CreateFloatImage
    np.testing.assert_allclose(w, [[0.299, 0.587, 0.114, 1.0]], atol=1e-6)
    e = np.asarray(Image(rgb).create_float_image(o3d.geometry.ColorToIntensityConversionType.Equal))
    np.testing.assert_allclose(e, [[1 / 3, 1 / 3, 1 / 3, 1.0]], atol=1e-6)
    depth = Image(np.array([[1000, 2500, 4000, 0]], dtype=np.uint16))
    d = np.asarray(depth.convert_depth_to_float_image(depth_scale=1000.0, depth_trunc=3.0))
    np.testing.assert_allclose(d, [[1.0, 2.5, 0.0, 0.0]])
    half = np.asarray(Image(np.arange(16, dtype=np.float32).reshape(4, 4)).downsample())
    np.testing.assert_allclose(half, [[2.5, 4.5], [10.5, 12.5]])


def test_copies_and_pickle():
    a = np.arange(12, dtype=np.uint8).reshape(3, 4)
    img = Image(a)
    for other in (Image(img), copy.copy(img), copy.deepcopy(img), pickle.loads(pickle.dumps(img))):
        np.testing.assert_array_equal(np.asarray(other), a)
        assert not np.shares_memory(np.asarray(other), np.asarray(img))
    assert Image().is_empty() and np.asarray(Image()).size == 0


@pytest.mark.parametrize("bad", [np.zeros((2, 2), dtype=np.float64), np.zeros((2, 2), dtype=np.int32),
                                 np.zeros((2, 2, 2), dtype=np.uint8), np.zeros(5, dtype=np.uint8),
                                 np.zeros((0, 3), dtype=np.uint8)])
def test_bad_arrays_raise(bad):
    with pytest.raises(ValueError):
        Image(bad)


def test_empty_image_operations_raise():
    with pytest.raises(ValueError):
        Image().flip_vertical()


def test_create_zero_filled():
    img = Image.create(5, 3, num_of_channels=3, bytes_per_channel=2)
    a = np.asarray(img)
    assert a.shape == (3, 5, 3) and a.dtype == np.uint16 and not a.any()
    assert np.asarray(Image.create(2, 2, bytes_per_channel=4)).dtype == np.float32
    with pytest.raises(ValueError):
        Image.create(0, 3)
    with pytest.raises(ValueError):
        Image.create(2, 2, num_of_channels=2)
