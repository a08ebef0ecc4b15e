import numpy as np
import pytest

import o3d


def two_clusters(rng):
    a = np.array([0.1, 0.1, 0.1]) + rng.uniform(-0.01, 0.01, size=(7, 3))
    b = np.array([5.0, 5.0, 5.0]) + rng.uniform(-0.01, 0.01, size=(5, 3))
    return a, b


def test_voxel_down_sample_averages_each_voxel(rng):
    a, b = two_clusters(rng)
    pcd = o3d.geometry.PointCloud(np.vstack([a, b]))
    pcd.colors = np.vstack([np.tile([1.0, 0, 0], (7, 1)), np.tile([0, 0, 1.0], (5, 1))])
    down = pcd.voxel_down_sample(1.0)
    pts = np.asarray(down.points)
    order = np.argsort(pts[:, 0])
    assert pts.shape == (2, 3)
    np.testing.assert_allclose(pts[order], np.vstack([a.mean(axis=0), b.mean(axis=0)]), atol=1e-12)
    np.testing.assert_allclose(np.asarray(down.colors)[order], [[1, 0, 0], [0, 0, 1]], atol=1e-12)
    assert len(pcd) == 12  # the input is untouched


def test_voxel_down_sample_bad_sizes():
    pcd = o3d.geometry.PointCloud(np.zeros((3, 3)))
    for bad in (float("nan"), 0.0, -1.0, float("inf")):
        with pytest.raises(ValueError):
            pcd.voxel_down_sample(bad)


def test_uniform_down_sample():
    pts = np.arange(30, dtype=float).reshape(10, 3)
    down = o3d.geometry.PointCloud(pts).uniform_down_sample(3)
    np.testing.assert_array_equal(np.asarray(down.points), pts[[0, 3, 6, 9]])
    with pytest.raises(ValueError):
        o3d.geometry.PointCloud(pts).uniform_down_sample(0)


def test_random_down_sample_is_seeded_ordered_subset(random_points):
    pcd = o3d.geometry.PointCloud(random_points)
    a = np.asarray(pcd.random_down_sample(0.3, seed=7).points)
    b = np.asarray(pcd.random_down_sample(0.3, seed=7).points)
    assert a.shape == (150, 3)
    np.testing.assert_array_equal(a, b)
    # every kept point comes from the input, in the input's order
    index = {tuple(p): i for i, p in enumerate(random_points)}
    kept = [index[tuple(p)] for p in a]
    assert kept == sorted(kept) and len(set(kept)) == 150
    assert len(pcd.random_down_sample(0.3).points) == 150  # unseeded: still the right count


def test_random_down_sample_bad_ratio():
    pcd = o3d.geometry.PointCloud(np.zeros((4, 3)))
    with pytest.raises(ValueError):
        pcd.random_down_sample(1.5, seed=1)


def test_farthest_point_down_sample_on_a_line():
    pts = np.column_stack([np.arange(11.0), np.zeros(11), np.zeros(11)])
    down = o3d.geometry.PointCloud(pts).farthest_point_down_sample(3)
    assert sorted(np.asarray(down.points)[:, 0].tolist()) == [0.0, 5.0, 10.0]
    down = o3d.geometry.PointCloud(pts).farthest_point_down_sample(2, start_index=4)
    assert sorted(np.asarray(down.points)[:, 0].tolist()) == [4.0, 10.0]
