import numpy as np

import o3d


def brute_nn(a, b, exclude_self=False):
    d = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)
    if exclude_self:
        np.fill_diagonal(d, np.inf)
    return d.min(axis=1)


def test_nearest_neighbor_distance_matches_brute_force(rng):
    pts = rng.uniform(size=(200, 3))
    d = o3d.geometry.PointCloud(pts).compute_nearest_neighbor_distance()
    d = np.asarray(d)
    assert d.shape == (200,)
    np.testing.assert_allclose(d, brute_nn(pts, pts, exclude_self=True), rtol=1e-12)


def test_point_cloud_distance_matches_brute_force(rng):
    a = rng.uniform(size=(150, 3))
    b = rng.uniform(size=(90, 3)) + 0.2
    d = np.asarray(o3d.geometry.PointCloud(a).compute_point_cloud_distance(o3d.geometry.PointCloud(b)))
    np.testing.assert_allclose(d, brute_nn(a, b), rtol=1e-12)
