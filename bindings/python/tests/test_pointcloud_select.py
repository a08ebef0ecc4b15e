import numpy as np
import pytest

import o3d


def test_select_by_index_and_invert():
    pts = np.arange(15, dtype=float).reshape(5, 3)
    pcd = o3d.geometry.PointCloud(pts)
    sel = pcd.select_by_index([0, 3])
    np.testing.assert_array_equal(np.asarray(sel.points), pts[[0, 3]])
    inv = pcd.select_by_index(np.array([0, 3]), invert=True)
    np.testing.assert_array_equal(np.asarray(inv.points), pts[[1, 2, 4]])
    assert len(pcd) == 5


def test_select_by_index_out_of_range():
    pcd = o3d.geometry.PointCloud(np.zeros((3, 3)))
    with pytest.raises(ValueError):
        pcd.select_by_index([5])
    with pytest.raises(ValueError):
        pcd.select_by_index([-1])
    with pytest.raises(ValueError):
        pcd.select_by_index([0.5])


def test_remove_non_finite_points():
    pts = np.array([[0, 0, 0], [np.nan, 0, 0], [np.inf, 1, 1], [1, 1, 1]], dtype=float)
    pcd = o3d.geometry.PointCloud(pts)
    pcd.remove_non_finite_points(remove_nan=True, remove_infinite=False)
    assert len(pcd) == 3
    pcd.remove_non_finite_points()
    np.testing.assert_array_equal(np.asarray(pcd.points), [[0, 0, 0], [1, 1, 1]])


def test_paint_uniform_color():
    pcd = o3d.geometry.PointCloud(np.zeros((4, 3)))
    assert pcd.paint_uniform_color([0.1, 0.2, 0.3]) is pcd
    assert pcd.has_colors()
    np.testing.assert_allclose(np.asarray(pcd.colors), np.tile([0.1, 0.2, 0.3], (4, 1)))


def test_normalize_normals():
    pcd = o3d.geometry.PointCloud(np.zeros((2, 3)))
    pcd.normals = np.array([[3.0, 0, 4], [0, 0, -2]])
    pcd.normalize_normals()
    np.testing.assert_allclose(np.asarray(pcd.normals), [[0.6, 0, 0.8], [0, 0, -1]])
