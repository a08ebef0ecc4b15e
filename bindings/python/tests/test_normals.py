import numpy as np
import pytest

import o3d

EXPECTED = np.array([-0.5, 0.0, 1.0]) / np.linalg.norm([-0.5, 0.0, 1.0])


def test_plane_normals_are_analytic(plane_points):
    pcd = o3d.geometry.PointCloud(plane_points)
    pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(knn=20))
    n = np.asarray(pcd.normals)
    assert n.shape == plane_points.shape
    np.testing.assert_allclose(np.abs(n @ EXPECTED), 1.0, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-12)


def test_default_and_hybrid_and_radius_params(plane_points):
    for param in (None, o3d.geometry.KDTreeSearchParamHybrid(radius=0.5, max_nn=30),
                  o3d.geometry.KDTreeSearchParamRadius(radius=0.5)):
        pcd = o3d.geometry.PointCloud(plane_points)
        if param is None:
            pcd.estimate_normals()
        else:
            pcd.estimate_normals(search_param=param)
        np.testing.assert_allclose(np.abs(np.asarray(pcd.normals) @ EXPECTED), 1.0, atol=1e-9)


def test_orient_to_direction(plane_points):
    pcd = o3d.geometry.PointCloud(plane_points)
    pcd.estimate_normals()
    pcd.orient_normals_to_align_with_direction()
    np.testing.assert_allclose(np.asarray(pcd.normals), np.tile(EXPECTED, (400, 1)), atol=1e-9)
    pcd.orient_normals_to_align_with_direction([0.0, 0.0, -1.0])
    np.testing.assert_allclose(np.asarray(pcd.normals), np.tile(-EXPECTED, (400, 1)), atol=1e-9)


def test_orient_towards_camera(plane_points):
    pcd = o3d.geometry.PointCloud(plane_points)
    pcd.estimate_normals()
    pcd.orient_normals_towards_camera_location([0.0, 0.0, -10.0])
    n = np.asarray(pcd.normals)
    assert np.all(n[:, 2] < 0)
    to_cam = np.array([0.0, 0.0, -10.0]) - plane_points
    assert np.all(np.sum(n * to_cam, axis=1) >= 0)


def test_existing_normals_orient_new_ones(plane_points):
    pcd = o3d.geometry.PointCloud(plane_points)
    pcd.normals = np.tile(-EXPECTED, (400, 1))
    pcd.estimate_normals()
    np.testing.assert_allclose(np.asarray(pcd.normals), np.tile(-EXPECTED, (400, 1)), atol=1e-9)


def test_bad_search_param():
    pcd = o3d.geometry.PointCloud(np.zeros((5, 3)))
    with pytest.raises(ValueError):
        pcd.estimate_normals("knn")
    with pytest.raises(ValueError):
        pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(knn=0))


def test_search_param_attributes():
    p = o3d.geometry.KDTreeSearchParamHybrid(radius=0.1, max_nn=30)
    assert p.radius == 0.1 and p.max_nn == 30
    assert o3d.geometry.KDTreeSearchParamKNN().knn == 30
    assert o3d.geometry.KDTreeSearchParamRadius(0.25).radius == 0.25
