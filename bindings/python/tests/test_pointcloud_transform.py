import numpy as np
import pytest

import o3d


def rot_z(deg):
    t = np.deg2rad(deg)
    return np.array([[np.cos(t), -np.sin(t), 0], [np.sin(t), np.cos(t), 0], [0, 0, 1]])


def test_bounds_center_and_aabb():
    pts = np.array([[0, 0, 0], [2, 0, 0], [0, 4, 0], [0, 0, 6]], dtype=float)
    pcd = o3d.geometry.PointCloud(pts)
    np.testing.assert_array_equal(pcd.get_min_bound(), [0, 0, 0])
    np.testing.assert_array_equal(pcd.get_max_bound(), [2, 4, 6])
    np.testing.assert_allclose(pcd.get_center(), [0.5, 1.0, 1.5])
    box = pcd.get_axis_aligned_bounding_box()
    assert isinstance(box, o3d.geometry.AxisAlignedBoundingBox)
    np.testing.assert_array_equal(box.min_bound, [0, 0, 0])
    np.testing.assert_array_equal(box.get_extent(), [2, 4, 6])
    np.testing.assert_array_equal(box.get_center(), [1, 2, 3])
    assert box.volume() == 48.0


def test_transform_applies_to_points_and_normals():
    pcd = o3d.geometry.PointCloud(np.array([[1.0, 0.0, 0.0]]))
    pcd.normals = np.array([[1.0, 0.0, 0.0]])
    T = np.eye(4)
    T[:3, :3] = rot_z(90)
    T[:3, 3] = [0, 0, 5]
    assert pcd.transform(T) is pcd
    np.testing.assert_allclose(np.asarray(pcd.points), [[0, 1, 5]], atol=1e-12)
    np.testing.assert_allclose(np.asarray(pcd.normals), [[0, 1, 0]], atol=1e-12)


def test_translate_relative_and_absolute():
    pcd = o3d.geometry.PointCloud(np.array([[0.0, 0, 0], [2, 2, 2]]))
    pcd.translate([1, 1, 1])
    np.testing.assert_allclose(pcd.get_center(), [2, 2, 2])
    pcd.translate([10, 0, 0], relative=False)
    np.testing.assert_allclose(pcd.get_center(), [10, 0, 0])
    np.testing.assert_allclose(np.asarray(pcd.points), [[9, -1, -1], [11, 1, 1]])


def test_rotate_about_center_and_given_point():
    pcd = o3d.geometry.PointCloud(np.array([[1.0, 0, 0], [3, 0, 0]]))
    pcd.rotate(rot_z(180))  # about its center (2, 0, 0)
    np.testing.assert_allclose(np.asarray(pcd.points), [[3, 0, 0], [1, 0, 0]], atol=1e-12)
    pcd.rotate(rot_z(90), center=[0, 0, 0])
    np.testing.assert_allclose(np.asarray(pcd.points), [[0, 3, 0], [0, 1, 0]], atol=1e-12)


def test_scale():
    pcd = o3d.geometry.PointCloud(np.array([[1.0, 1, 1], [3, 3, 3]]))
    pcd.scale(2.0, center=[0, 0, 0])
    np.testing.assert_allclose(np.asarray(pcd.points), [[2, 2, 2], [6, 6, 6]])
    pcd.scale(0.5)  # about the center (4, 4, 4)
    np.testing.assert_allclose(np.asarray(pcd.points), [[3, 3, 3], [5, 5, 5]])


def test_bad_matrix_shapes_raise():
    pcd = o3d.geometry.PointCloud(np.zeros((2, 3)))
    with pytest.raises(ValueError):
        pcd.transform(np.eye(3))
    with pytest.raises(ValueError):
        pcd.rotate(np.eye(4))
    with pytest.raises(ValueError):
        pcd.translate([1, 2])
