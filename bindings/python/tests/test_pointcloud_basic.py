import copy

import numpy as np
import pytest

import o3d


def test_empty_cloud():
    pcd = o3d.geometry.PointCloud()
    assert len(pcd) == 0
    assert not pcd.has_points() and not pcd.has_normals() and not pcd.has_colors()
    assert pcd.is_empty()
    assert np.asarray(pcd.points).shape == (0, 3)
    assert "0 points" in repr(pcd)


def test_set_points_normals_colors(random_points):
    pcd = o3d.geometry.PointCloud()
    pcd.points = o3d.utility.Vector3dVector(random_points)
    assert len(pcd) == 500 and pcd.has_points()
    np.testing.assert_array_equal(np.asarray(pcd.points), random_points)
    pcd.normals = random_points / np.linalg.norm(random_points, axis=1, keepdims=True)
    pcd.colors = np.full((500, 3), 0.25)
    assert pcd.has_normals() and pcd.has_colors()
    np.testing.assert_allclose(np.linalg.norm(np.asarray(pcd.normals), axis=1), 1.0)
    assert np.all(np.asarray(pcd.colors) == 0.25)


def test_constructor_with_points_and_copy(random_points):
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(random_points))
    for dup in (o3d.geometry.PointCloud(pcd), copy.copy(pcd), copy.deepcopy(pcd)):
        np.asarray(dup.points)[0] = 100.0
        assert np.asarray(pcd.points)[0, 0] == random_points[0, 0]
        assert np.asarray(dup.points)[0, 0] == 100.0


def test_clear(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    pcd.paint_uniform_color([1, 0, 0])
    assert pcd.clear() is pcd
    assert len(pcd) == 0 and not pcd.has_colors()


def test_add_and_iadd():
    a = o3d.geometry.PointCloud(np.zeros((2, 3)))
    b = o3d.geometry.PointCloud(np.ones((3, 3)))
    c = a + b
    assert len(c) == 5 and len(a) == 2
    np.testing.assert_array_equal(np.asarray(c.points)[2:], np.ones((3, 3)))
    a += b
    assert len(a) == 5
    a += a
    assert len(a) == 10


def test_add_keeps_normals_only_when_both_have_them():
    a = o3d.geometry.PointCloud(np.zeros((2, 3)))
    a.normals = np.tile([0.0, 0.0, 1.0], (2, 1))
    b = o3d.geometry.PointCloud(np.ones((2, 3)))
    assert not (a + b).has_normals()
    b.normals = np.tile([0.0, 1.0, 0.0], (2, 1))
    assert (a + b).has_normals()


def test_points_setter_rejects_bad_shapes():
    pcd = o3d.geometry.PointCloud()
    with pytest.raises(ValueError):
        pcd.points = np.zeros((5, 2))
    with pytest.raises(ValueError):
        pcd.points = np.zeros(6)
    with pytest.raises(ValueError):
        pcd.points = "abc"
    assert len(pcd) == 0


def test_points_setter_accepts_lists_and_ints():
    pcd = o3d.geometry.PointCloud()
    pcd.points = [[1, 2, 3], [4, 5, 6]]
    assert np.asarray(pcd.points).dtype == np.float64
    np.testing.assert_array_equal(np.asarray(pcd.points), [[1, 2, 3], [4, 5, 6]])


def test_copy_out_and_readonly_view(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    snap = pcd._array_copy(0)
    ro = pcd._readonly_view(0)
    assert not ro.flags.writeable
    np.testing.assert_array_equal(snap, random_points)
    np.testing.assert_array_equal(ro, random_points)
    np.asarray(pcd.points)[0] = 9.0
    assert snap[0, 0] == random_points[0, 0]
    assert ro[0, 0] == 9.0


def test_pickle_round_trip(random_points):
    import pickle

    pcd = o3d.geometry.PointCloud(random_points)
    pcd.colors = np.full((500, 3), 0.5)
    back = pickle.loads(pickle.dumps(pcd))
    np.testing.assert_array_equal(np.asarray(back.points), random_points)
    assert back.has_colors() and not back.has_normals()
    assert len(pickle.loads(pickle.dumps(o3d.geometry.PointCloud()))) == 0
