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


# ---- orient_normals_consistent_tangent_plane

def sphere_with_flipped_normals(n=1000, seed=3):
    """Fibonacci-sphere points with their outward normals, a random half of them flipped."""
    i = np.arange(n) + 0.5
    z = 1.0 - 2.0 * i / n
    r = np.sqrt(1.0 - z * z)
    phi = np.pi * (3.0 - np.sqrt(5.0)) * i
    outward = np.column_stack([r * np.cos(phi), r * np.sin(phi), z])
    flip = np.random.default_rng(seed).uniform(size=n) < 0.5
    pcd = o3d.geometry.PointCloud(outward)
    pcd.normals = np.where(flip[:, None], -outward, outward)
    return pcd, outward


def test_consistent_tangent_plane_makes_normals_agree():
    pcd, outward = sphere_with_flipped_normals()
    assert pcd.orient_normals_consistent_tangent_plane(10) is None  # as Open3D
    dots = np.einsum("ij,ij->i", np.asarray(pcd.normals), outward)
    np.testing.assert_allclose(np.abs(dots), 1.0, atol=1e-12)  # only signs change
    assert np.all(dots > 0) or np.all(dots < 0)  # one global sign


def test_consistent_tangent_plane_keywords():
    for kwargs in ({"lambda_penalty": 0.5}, {"cos_alpha_tol": 0.5}, {"lambda_penalty": 1.0, "cos_alpha_tol": 0.9}):
        pcd, outward = sphere_with_flipped_normals(seed=4)
        pcd.orient_normals_consistent_tangent_plane(k=12, **kwargs)
        dots = np.einsum("ij,ij->i", np.asarray(pcd.normals), outward)
        assert np.all(dots > 0) or np.all(dots < 0), kwargs


def test_consistent_tangent_plane_keeps_views():
    pcd, _ = sphere_with_flipped_normals()
    view = np.asarray(pcd.normals)
    pcd.orient_normals_consistent_tangent_plane(10)
    np.testing.assert_array_equal(view, np.asarray(pcd.normals))  # flipped in place: the view sees it


def test_consistent_tangent_plane_errors():
    with pytest.raises(o3d.InvalidArgumentError, match="normal"):
        o3d.geometry.PointCloud(np.random.default_rng(0).uniform(size=(50, 3))).orient_normals_consistent_tangent_plane(5)
    pcd, _ = sphere_with_flipped_normals(200)
    for args in ((0,), (-1,), (5, -1.0), (5, np.nan), (5, np.inf)):
        with pytest.raises(o3d.InvalidArgumentError):
            pcd.orient_normals_consistent_tangent_plane(*args)
    with pytest.raises(TypeError):
        pcd.orient_normals_consistent_tangent_plane()  # k is required, as in Open3D
