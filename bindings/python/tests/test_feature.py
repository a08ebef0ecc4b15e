"""Feature, compute_fpfh_feature, correspondences_from_features, read/write_feature and KDTreeFlann over
features. Reference numbers: tools/reference/record_python_registration.py (Open3D 0.20), quoted by name."""
import copy
import pickle

import numpy as np
import pytest

import o3d
from o3d.pipelines import registration as reg

FEATURE_DIR = "open3d/Feature"


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


@pytest.fixture
def stored(data_file):
    return (o3d.io.read_feature(data_file(f"{FEATURE_DIR}/cloud_bin_0.fpfh.bin")),
            o3d.io.read_feature(data_file(f"{FEATURE_DIR}/cloud_bin_1.fpfh.bin")))


@pytest.fixture
def clouds(data_file):
    return (o3d.io.read_point_cloud(data_file(f"{FEATURE_DIR}/cloud_bin_0.pcd")),
            o3d.io.read_point_cloud(data_file(f"{FEATURE_DIR}/cloud_bin_1.pcd")))


@pytest.fixture
def small_cloud(rng):
    pts = rng.uniform(-1.0, 1.0, size=(300, 3)) * [1.0, 0.7, 0.2]
    pcd = o3d.geometry.PointCloud(pts)
    pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(12))
    return pcd


HYBRID = o3d.geometry.KDTreeSearchParamHybrid(radius=0.25, max_nn=100)


# ---- Feature value

def test_empty_feature():
    f = reg.Feature()
    assert (f.dimension(), f.num()) == (0, 0)
    assert f.data.shape == (0, 0)
    assert "dimension = 0 and num = 0" in repr(f)


def test_data_is_a_writable_zero_copy_view():
    f = reg.Feature()
    f.resize(4, 3)
    d = f.data
    assert d.shape == (4, 3) and d.dtype == np.float64 and d.flags.f_contiguous
    assert not d.any()
    d[2, 1] = 5.0  # write through the view ...
    assert f.data[2, 1] == 5.0  # ... seen by a fresh view of the same memory
    assert np.shares_memory(d, f.data)


def test_resize_keeps_values_and_old_views_stay_valid():
    f = reg.Feature()
    f.data = np.arange(12.0).reshape(3, 4)
    view = f.data
    f.resize(3, 6)
    assert (f.dimension(), f.num()) == (3, 6)
    np.testing.assert_array_equal(f.data[:, :4], np.arange(12.0).reshape(3, 4))
    assert not f.data[:, 4:].any()
    np.testing.assert_array_equal(view, np.arange(12.0).reshape(3, 4))  # the old view kept its matrix
    view[0, 0] = -1.0
    assert f.data[0, 0] == 0.0


def test_assign_data_and_select_by_index():
    f = reg.Feature()
    f.data = np.arange(10.0).reshape(2, 5)  # 5 descriptors of length 2
    assert (f.dimension(), f.num()) == (2, 5)
    picked = f.select_by_index([4, 1])
    np.testing.assert_array_equal(picked.data, [[4.0, 1.0], [9.0, 6.0]])
    rest = f.select_by_index([4, 1], invert=True)
    np.testing.assert_array_equal(rest.data, [[0.0, 2.0, 3.0], [5.0, 7.0, 8.0]])
    with pytest.raises(o3d.InvalidArgumentError):
        f.select_by_index([5])
    with pytest.raises(o3d.InvalidArgumentError):
        f.data = np.array([[np.nan, 1.0]])
    with pytest.raises(ValueError):
        f.data = np.zeros(3)  # not (dimension, num)


def test_copies_are_deep():
    f = reg.Feature()
    f.data = np.ones((3, 2))
    for other in (reg.Feature(f), copy.copy(f), copy.deepcopy(f), pickle.loads(pickle.dumps(f))):
        np.testing.assert_array_equal(other.data, f.data)
        other.data[0, 0] = 7.0
        assert f.data[0, 0] == 1.0


# ---- files

def test_read_stored_features(stored):
    f0, f1 = stored
    # record_python_registration.py: stored0.shape, stored0.fp, stored0.column0 (first 3), stored1.*
    assert f0.data.shape == (33, 3903) and f1.data.shape == (33, 3458)
    assert (f0.dimension(), f0.num()) == (33, 3903)
    assert fp(f0.data) == pytest.approx(75809741254.15752, rel=1e-13)
    assert fp(f1.data) == pytest.approx(59472948465.32669, rel=1e-13)
    np.testing.assert_array_equal(f0.data[:3, 0], [6.711965560913086, 2.783480167388916, 4.1213698387146])
    np.testing.assert_array_equal(f1.data[:3, 0], [1.5715090036392212, 1.4037026166915894, 4.983343601226807])


def test_write_read_round_trip_in_open3d_layout(tmp_path, rng):
    f = reg.Feature()
    f.data = rng.normal(size=(5, 7))
    path = tmp_path / "f.bin"
    assert o3d.io.write_feature(str(path), f) is True
    raw = path.read_bytes()
    header = np.frombuffer(raw[:8], dtype=np.int32)
    assert header.tolist() == [5, 7] and len(raw) == 8 + 5 * 7 * 8
    body = np.frombuffer(raw[8:], dtype=np.float64).reshape(7, 5)  # descriptor by descriptor
    np.testing.assert_array_equal(body.T, f.data)
    back = o3d.io.read_feature(path)  # os.PathLike works too
    np.testing.assert_array_equal(back.data, f.data)


def test_read_feature_errors(tmp_path):
    with pytest.raises(o3d.O3DFileNotFoundError):
        o3d.io.read_feature(str(tmp_path / "missing.bin"))
    bad = tmp_path / "truncated.bin"
    bad.write_bytes(np.array([33, 10], dtype=np.int32).tobytes() + b"\0" * 100)
    with pytest.raises(o3d.ParseError):
        o3d.io.read_feature(str(bad))


# ---- FPFH

def test_fpfh_matches_open3d(clouds):
    cloud0, _ = clouds
    f = reg.compute_fpfh_feature(cloud0, HYBRID)
    d = f.data
    # record_python_registration.py: fpfh0.shape, fpfh0.sum, fpfh0.fp, fpfh0.column0 (first 6), fpfh0.column1000
    assert d.shape == (33, 3903)
    np.testing.assert_allclose(d.sum(axis=0), 600.0, rtol=1e-9)  # three histograms of 200 each
    assert fp(d) == pytest.approx(151427046117.47833, rel=1e-7)
    np.testing.assert_allclose(d[:6, 0], [6.725477174570882, 2.7893635254886777, 3.9888894905675807,
                                          10.804858986809654, 20.468476999546898, 101.19109442668875], rtol=1e-6)
    np.testing.assert_allclose(d[:6, 1000], [4.190229801939799, 7.26554758946481, 0.36413400811250723,
                                             0.987761625591737, 5.491845852391035, 147.0858242897292], rtol=1e-6)
    knn = reg.compute_fpfh_feature(cloud0, o3d.geometry.KDTreeSearchParamKNN(30))
    assert fp(knn.data) == pytest.approx(150503370894.72342, rel=1e-7)  # fpfh0_knn30.fp


def test_fpfh_indices_select_points(clouds):
    cloud0, _ = clouds
    full = reg.compute_fpfh_feature(cloud0, HYBRID)
    sub = reg.compute_fpfh_feature(cloud0, HYBRID, [5, 1000, 17])
    np.testing.assert_allclose(sub.data, full.data[:, [5, 17, 1000]], rtol=1e-12)  # ascending, as Open3D
    assert fp(sub.data) == pytest.approx(91306.96967813118, rel=1e-7)  # fpfh0_indices.fp
    assert reg.compute_fpfh_feature(cloud0, HYBRID, [17, 5, 5]).num() == 2  # duplicates once, as Open3D
    empty = reg.compute_fpfh_feature(cloud0, HYBRID, [])
    assert (empty.dimension(), empty.num()) == (33, 0)  # as Open3D


def test_fpfh_thread_count_does_not_change_result(small_cloud):
    one = reg.compute_fpfh_feature(small_cloud, o3d.geometry.KDTreeSearchParamKNN(20), num_threads=1)
    two = reg.compute_fpfh_feature(small_cloud, o3d.geometry.KDTreeSearchParamKNN(20), num_threads=2)
    np.testing.assert_array_equal(one.data, two.data)


def test_fpfh_errors(small_cloud):
    bare = o3d.geometry.PointCloud(np.asarray(small_cloud.points))
    with pytest.raises(o3d.InvalidArgumentError):
        reg.compute_fpfh_feature(bare, HYBRID)  # no normals
    with pytest.raises(o3d.InvalidArgumentError):
        reg.compute_fpfh_feature(small_cloud, HYBRID, [300])  # index out of range
    with pytest.raises(o3d.InvalidArgumentError):
        reg.compute_fpfh_feature(small_cloud, o3d.geometry.KDTreeSearchParamRadius(float("nan")))
    with pytest.raises(ValueError):
        reg.compute_fpfh_feature(small_cloud, "radius")
    with pytest.raises(TypeError):
        reg.compute_fpfh_feature(np.zeros((3, 3)), HYBRID)


# ---- KD-trees over features

def brute_force_knn(data, query, k):
    d2 = ((data - query) ** 2).sum(axis=1)
    order = np.argsort(d2, kind="stable")[:k]
    return order, d2[order]


def test_kdtree_on_feature_agrees_with_brute_force(stored, rng):
    f0, f1 = stored
    tree = o3d.geometry.KDTreeFlann(f0)
    columns = f0.data.T  # (3903, 33)
    for j in rng.choice(f1.num(), size=15, replace=False):
        q = f1.data[:, j]
        k, idx, d2 = tree.search_knn_vector_xd(q, 5)
        want_idx, want_d2 = brute_force_knn(columns, q, 5)
        assert k == 5
        np.testing.assert_array_equal(idx, want_idx)
        np.testing.assert_allclose(d2, want_d2, rtol=1e-9)
        radius = float(np.sqrt(want_d2[-1])) * 1.0001
        k, idx, d2 = tree.search_radius_vector_xd(q, radius)
        assert sorted(idx.tolist()) == sorted(np.flatnonzero(((columns - q) ** 2).sum(axis=1) <= radius ** 2).tolist())
        k, idx, _ = tree.search_hybrid_vector_xd(q, radius, 3)
        assert k == 3 and idx.tolist() == want_idx[:3].tolist()
        k, idx, _ = tree.search_vector_xd(q, o3d.geometry.KDTreeSearchParamKNN(2))
        assert idx.tolist() == want_idx[:2].tolist()


def test_kdtree_set_feature_batch_and_xd_arrays(stored):
    f0, f1 = stored
    tree = o3d.geometry.KDTreeFlann()
    assert tree.set_feature(f0) is True
    queries = f1.data[:, :50].T.copy()  # (50, 33)
    offsets, idx, d2 = tree.search_knn(queries, 1)
    assert offsets.tolist() == list(range(51))
    for i in range(0, 50, 7):
        assert idx[i] == brute_force_knn(f0.data.T, queries[i], 1)[0][0]
    rows = o3d.geometry.KDTreeFlann(f0.data.T.copy())  # (N, d) array: one point per row
    assert rows.search_knn_vector_xd(queries[3], 4)[1].tolist() == tree.search_knn_vector_xd(queries[3], 4)[1].tolist()
    with pytest.raises(o3d.InvalidArgumentError):
        tree.search_knn_vector_xd(np.zeros(3), 1)  # wrong dimension
    with pytest.raises(o3d.InvalidArgumentError):
        tree.search_knn_vector_3d([0.0, 0.0, 0.0], 1)


def test_matching_quality_of_stored_and_our_features(stored, clouds):
    """Share of cloud_bin_1's points whose nearest descriptor in cloud_bin_0 lies within 0.075 m of them."""
    (f0, f1), (c0, c1) = stored, clouds
    p0, p1 = np.asarray(c0.points), np.asarray(c1.points)

    def share(feature0, feature1):
        _, idx, _ = o3d.geometry.KDTreeFlann(feature0).search_knn(feature1.data.T.copy(), 1)
        return float(np.mean(np.linalg.norm(p0[idx] - p1, axis=1) < 0.075))

    stored_share = share(f0, f1)
    assert stored_share == pytest.approx(0.1139386928860613, abs=1e-12)  # matching.stored (394 of 3458)
    ours = share(reg.compute_fpfh_feature(c0, HYBRID), reg.compute_fpfh_feature(c1, HYBRID))
    assert ours == pytest.approx(0.10786581839213419, abs=0.005)  # matching.fpfh_r025 (Open3D's FPFH)
    assert abs(ours - stored_share) < 0.02  # within two points of the stored features


# ---- correspondences

def test_correspondences_from_features(stored):
    f0, f1 = stored
    all_pairs = reg.correspondences_from_features(f0, f1)
    assert isinstance(all_pairs, o3d.utility.Vector2iVector)
    c = np.asarray(all_pairs)
    assert c.shape == (3903, 2) and c.dtype == np.int32
    np.testing.assert_array_equal(c[:, 0], np.arange(3903))
    assert fp(c) == 64248785259.0  # corres.mutual=False.fp
    mutual = np.asarray(reg.correspondences_from_features(f0, f1, True))
    assert len(mutual) == 498 and fp(mutual) == 1053431982.0  # corres.mutual=True.n / .fp
    # fewer than 50% survive the mutual filter: Open3D's rule returns every pair instead
    assert len(reg.correspondences_from_features(f0, f1, True, 0.5)) == 3903


def test_correspondence_errors(stored):
    f0, _ = stored
    short = reg.Feature()
    short.data = np.zeros((10, 4))
    with pytest.raises(o3d.InvalidArgumentError):
        reg.correspondences_from_features(f0, short)  # mismatched dimensions
    with pytest.raises(TypeError):
        reg.correspondences_from_features(f0, np.zeros((33, 4)))
