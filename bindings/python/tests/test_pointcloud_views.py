"""np.asarray(pcd.points) is a zero-copy, writable view that keeps the cloud's memory alive."""
import gc

import numpy as np

import o3d


def test_view_is_zero_copy_and_writable(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    v = np.asarray(pcd.points)
    assert v.dtype == np.float64 and v.shape == (500, 3)
    assert v.flags.writeable and v.flags.c_contiguous
    assert not v.flags.owndata
    assert v.base is not None
    # Same memory on every access.
    assert np.asarray(pcd.points).ctypes.data == v.ctypes.data
    assert np.shares_memory(np.asarray(pcd.points), v)


def test_in_place_edit_is_visible_to_the_library():
    pcd = o3d.geometry.PointCloud(np.zeros((4, 3)))
    np.testing.assert_array_equal(pcd.get_center(), [0, 0, 0])
    np.asarray(pcd.points)[:] += [1.0, 2.0, 3.0]
    np.testing.assert_allclose(pcd.get_center(), [1.0, 2.0, 3.0])
    np.asarray(pcd.points)[0, 0] = 10.0
    assert pcd.get_max_bound()[0] == 10.0


def test_view_keeps_memory_alive_after_cloud_is_deleted(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    v = np.asarray(pcd.points)
    del pcd
    gc.collect()
    np.testing.assert_array_equal(v, random_points)  # would read freed memory otherwise


def test_view_survives_resizing_calls(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    old = np.asarray(pcd.points)
    pcd.points = np.zeros((2, 3))  # reallocation: the old view keeps the old data, never dangles
    pcd.paint_uniform_color([1, 0, 0])
    pcd.clear()
    np.testing.assert_array_equal(old, random_points)
    assert len(pcd) == 0


def test_transform_in_place_is_seen_through_view():
    pcd = o3d.geometry.PointCloud(np.zeros((3, 3)))
    v = np.asarray(pcd.points)
    pcd.translate([1.0, 0.0, 0.0])
    np.testing.assert_array_equal(v[:, 0], [1.0, 1.0, 1.0])


def test_float32_input_is_taken_without_python_conversion():
    a32 = (np.arange(30, dtype=np.float32).reshape(10, 3) / 7).astype(np.float32)
    pcd = o3d.geometry.PointCloud()
    pcd.points = a32
    out = np.asarray(pcd.points)
    assert out.dtype == np.float64
    np.testing.assert_array_equal(out, a32.astype(np.float64))
    pcd.normals = o3d.utility.Vector3dVector(a32)
    np.testing.assert_array_equal(np.asarray(pcd.normals), a32.astype(np.float64))
    pcd.colors = np.asfortranarray(np.full((10, 3), 0.5, dtype=np.float32))
    np.testing.assert_array_equal(np.asarray(pcd.colors), 0.5)


def test_non_contiguous_input():
    big = np.arange(60, dtype=np.float64).reshape(10, 6)
    pcd = o3d.geometry.PointCloud(big[:, ::2])
    np.testing.assert_array_equal(np.asarray(pcd.points), big[:, ::2])


def test_normals_and_colors_views_are_writable():
    pcd = o3d.geometry.PointCloud(np.zeros((3, 3)))
    pcd.normals = np.tile([0.0, 0.0, 2.0], (3, 1))
    np.asarray(pcd.normals)[:, 2] = 5.0
    pcd.normalize_normals()
    np.testing.assert_allclose(np.asarray(pcd.normals), np.tile([0.0, 0.0, 1.0], (3, 1)))
