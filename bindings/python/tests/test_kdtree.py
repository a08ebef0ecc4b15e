import numpy as np
import pytest

import o3d


@pytest.fixture
def cloud(rng):
    return rng.uniform(-1, 1, size=(300, 3))


def brute(points, q):
    d2 = np.sum((points - q) ** 2, axis=1)
    order = np.argsort(d2)
    return order, d2[order]


def test_knn_vector_matches_brute_force(cloud):
    tree = o3d.geometry.KDTreeFlann(o3d.geometry.PointCloud(cloud))
    q = np.array([0.1, -0.2, 0.3])
    k, idx, d2 = tree.search_knn_vector_3d(q, 10)
    order, bd2 = brute(cloud, q)
    assert k == 10
    np.testing.assert_array_equal(np.asarray(idx), order[:10])
    np.testing.assert_allclose(np.asarray(d2), bd2[:10], rtol=1e-12)


def test_radius_and_hybrid_vector(cloud):
    tree = o3d.geometry.KDTreeFlann(cloud)  # (N, 3) array
    q = cloud[17]
    order, bd2 = brute(cloud, q)
    k, idx, d2 = tree.search_radius_vector_3d(q, 0.4)
    inside = order[bd2 <= 0.16]
    assert k == len(inside)
    assert set(np.asarray(idx).tolist()) == set(inside.tolist())
    assert np.all(np.diff(np.asarray(d2)) >= 0)
    k, idx, d2 = tree.search_hybrid_vector_3d(q, 0.4, 5)
    assert k == min(5, len(inside))
    np.testing.assert_array_equal(np.asarray(idx), inside[:k])
    assert idx[0] == 17 and d2[0] == 0.0
    k2, idx2, _ = tree.search_vector_3d(q, o3d.geometry.KDTreeSearchParamKNN(3))
    np.testing.assert_array_equal(np.asarray(idx2), order[:3])


def test_batch_knn_matches_brute_force(cloud, rng):
    tree = o3d.geometry.KDTreeFlann(o3d.geometry.PointCloud(cloud))
    queries = rng.uniform(-1, 1, size=(40, 3))
    offsets, idx, d2 = tree.search_knn(queries, 5)
    assert offsets.dtype == np.int64 and idx.dtype == np.int32 and d2.dtype == np.float64
    np.testing.assert_array_equal(offsets, np.arange(41) * 5)
    for i, q in enumerate(queries):
        order, bd2 = brute(cloud, q)
        np.testing.assert_array_equal(idx[offsets[i]:offsets[i + 1]], order[:5])
        np.testing.assert_allclose(d2[offsets[i]:offsets[i + 1]], bd2[:5], rtol=1e-12)


def test_batch_radius_and_hybrid(cloud, rng):
    tree = o3d.geometry.KDTreeFlann(cloud)
    queries = rng.uniform(-1, 1, size=(20, 3))
    offsets, idx, d2 = tree.search_radius(queries, 0.3)
    assert len(offsets) == 21 and offsets[0] == 0 and offsets[-1] == len(idx) == len(d2)
    for i, q in enumerate(queries):
        order, bd2 = brute(cloud, q)
        assert set(idx[offsets[i]:offsets[i + 1]].tolist()) == set(order[bd2 <= 0.09].tolist())
    offsets, idx, _ = tree.search_hybrid(queries, 0.3, 2)
    counts = np.diff(offsets)
    assert np.all(counts <= 2)
    offsets2, idx2, _ = tree.search(queries, o3d.geometry.KDTreeSearchParamHybrid(0.3, 2))
    np.testing.assert_array_equal(idx, idx2)


def test_float32_queries_and_thread_independence(cloud, rng):
    tree = o3d.geometry.KDTreeFlann(cloud)
    q = rng.uniform(-1, 1, size=(64, 3)).astype(np.float32)
    o1, i1, _ = tree.search_knn(q, 4, num_threads=1)
    o2, i2, _ = tree.search_knn(q.astype(np.float64), 4, num_threads=2)
    np.testing.assert_array_equal(o1, o2)
    np.testing.assert_array_equal(i1, i2)


def test_batch_results_outlive_tree(cloud):
    tree = o3d.geometry.KDTreeFlann(cloud)
    offsets, idx, d2 = tree.search_knn(cloud[:3], 1)
    del tree
    np.testing.assert_array_equal(idx, [0, 1, 2])
    np.testing.assert_array_equal(d2, [0, 0, 0])


def test_tree_copies_points(cloud):
    pcd = o3d.geometry.PointCloud(cloud)
    tree = o3d.geometry.KDTreeFlann(pcd)
    assert tree.size() == 300 and len(tree) == 300
    pcd.points = np.zeros((1, 3))
    del pcd
    k, idx, _ = tree.search_knn_vector_3d(cloud[5], 1)
    assert k == 1 and idx[0] == 5


def test_empty_tree_and_bad_queries(cloud):
    with pytest.raises(ValueError):
        o3d.geometry.KDTreeFlann().search_knn_vector_3d([0, 0, 0], 1)
    tree = o3d.geometry.KDTreeFlann()
    assert tree.set_geometry(o3d.geometry.PointCloud(cloud))
    with pytest.raises(ValueError):
        tree.search_knn(np.zeros((4, 2)), 1)
    with pytest.raises(ValueError):
        tree.search_knn_vector_3d([0, 0], 1)
    with pytest.raises(ValueError):
        o3d.geometry.KDTreeFlann(np.array([[0.0, np.nan, 0.0]]))
