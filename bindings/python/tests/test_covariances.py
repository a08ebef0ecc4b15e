"""PointCloud.covariances, has_covariances, estimate_covariances.

Reference numbers: tools/reference/record_python_round2.py (Open3D 0.20.0), on round2_data.make_inputs().
"""
import numpy as np
import pytest

import o3d
from round2_data import fp, make_cloud


def test_default_empty():
    pcd = make_cloud()
    assert not pcd.has_covariances()
    assert np.asarray(pcd.covariances).shape == (0, 3, 3)


def test_set_get_roundtrip():
    pcd = make_cloud()
    asym = np.random.default_rng(0).normal(size=(200, 3, 3))
    with pytest.raises(o3d.InvalidArgumentError, match="not symmetric"):  # covariances are symmetric
        pcd.covariances = asym
    assert not pcd.has_covariances()
    covs = asym + asym.transpose(0, 2, 1)
    pcd.covariances = covs
    assert pcd.has_covariances()
    view = np.asarray(pcd.covariances)
    assert view.shape == (200, 3, 3) and np.array_equal(view, covs) and not view.flags.writeable
    assert view.base is not None and np.shares_memory(view, np.asarray(pcd.covariances))  # zero-copy
    assert np.array_equal(pcd._array_copy(3), covs)
    pcd.covariances = o3d.utility.Matrix3dVector(covs[::-1])
    assert np.array_equal(np.asarray(pcd.covariances), covs[::-1])
    assert np.array_equal(view, covs)  # the old view keeps the old data
    pcd.covariances = np.zeros((0, 3, 3))
    assert not pcd.has_covariances()


def test_follow_points():
    pcd = make_cloud()
    covs = np.arange(200 * 9, dtype=float).reshape(200, 3, 3)
    covs = covs + covs.transpose(0, 2, 1)
    pcd.covariances = covs
    sub = pcd.select_by_index([3, 7])
    assert np.array_equal(np.asarray(sub.covariances), covs[[3, 7]])
    R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    pcd.rotate(R, center=(0, 0, 0))
    assert np.allclose(np.asarray(pcd.covariances)[5], R @ covs[5] @ R.T)


def test_estimate_matches_open3d():
    pcd = make_cloud()
    pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamKNN(knn=10))
    c = np.asarray(pcd.covariances)
    assert c.shape == (200, 3, 3)
    assert fp(c) == pytest.approx(69029.5035913928, rel=1e-9)  # Open3D 0.20
    assert np.allclose(c[0], [[0.2727279985650739, -0.02571862643310685, 0.05056969809599837],
                              [-0.02571862643310685, 0.05531828238113734, 0.0036843829626338476],
                              [0.05056969809599837, 0.0036843829626338476, 0.07627247908267928]], atol=1e-12)
    pcd.estimate_covariances()  # KNN 30
    assert fp(pcd.covariances) == pytest.approx(159361.50214055862, rel=1e-9)
    pcd.estimate_covariances(search_param=o3d.geometry.KDTreeSearchParamRadius(radius=0.5))
    assert fp(pcd.covariances) == pytest.approx(284437.30862378294, rel=1e-9)


def test_estimate_analytic():
    # 4 points: the covariance of the whole set (divided by N) for every point with knn >= 4
    pts = np.array([[0.0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2]])
    pcd = o3d.geometry.PointCloud(pts)
    pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamKNN(knn=4))
    expected = np.cov(pts.T, bias=True)
    for c in np.asarray(pcd.covariances):
        assert np.allclose(c, expected)
    # fewer than 3 neighbours: identity (Open3D)
    pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamKNN(knn=2))
    assert np.allclose(np.asarray(pcd.covariances), np.eye(3))


def test_errors():
    pcd = make_cloud()
    with pytest.raises(ValueError):
        pcd.covariances = np.zeros((200, 3))
    with pytest.raises(ValueError):
        pcd.covariances = None
    with pytest.raises(ValueError):
        pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamKNN(knn=0))
