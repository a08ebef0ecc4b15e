"""PointCloud tools: outlier removal, crop, segment_plane, cluster_dbscan, mean/covariance, Mahalanobis."""
import threading

import numpy as np
import pytest

import o3d


def grid_plane(n=20, spacing=0.1):
    """n*n points on a regular grid in z = 0 (spacing 0.1)."""
    xs, ys = np.meshgrid(np.arange(n) * spacing, np.arange(n) * spacing, indexing="ij")
    return np.column_stack([xs.ravel(), ys.ravel(), np.zeros(n * n)])


def with_outliers(base, outliers, positions):
    """Insert `outliers` into `base` at row `positions` (sorted); returns (points, inlier indices)."""
    n = len(base) + len(outliers)
    is_out = np.zeros(n, dtype=bool)
    is_out[positions] = True
    pts = np.empty((n, 3))
    pts[~is_out] = base
    pts[is_out] = outliers
    return pts, np.flatnonzero(~is_out)


FAR = np.array([[10.0, 0, 5], [-8.0, 12, 0], [0.5, 0.5, 30.0]])
FAR_AT = [0, 157, 402]


# ---- remove_statistical_outlier ----

def test_statistical_outlier_keeps_exact_plane_indices():
    pts, inliers = with_outliers(grid_plane(), FAR, FAR_AT)
    pcd = o3d.geometry.PointCloud(pts)
    cl, ind = pcd.remove_statistical_outlier(nb_neighbors=20, std_ratio=2.0)
    assert isinstance(cl, o3d.geometry.PointCloud)
    assert list(ind) == inliers.tolist()
    assert all(isinstance(i, int) for i in ind)
    np.testing.assert_array_equal(np.asarray(cl.points), pts[inliers])
    assert len(pcd) == len(pts)  # input untouched
    # the indices feed select_by_index, as in the Open3D tutorial
    np.testing.assert_array_equal(np.asarray(pcd.select_by_index(ind).points), pts[inliers])
    np.testing.assert_array_equal(np.asarray(pcd.select_by_index(ind, invert=True).points), FAR)


def test_statistical_outlier_keeps_normals_and_colors():
    pts, inliers = with_outliers(grid_plane(10), FAR, [0, 50, 102])
    pcd = o3d.geometry.PointCloud(pts)
    colors = np.random.default_rng(1).uniform(size=pts.shape)
    pcd.colors = colors
    pcd.normals = np.tile([0.0, 0.0, 1.0], (len(pts), 1))
    cl, ind = pcd.remove_statistical_outlier(10, 1.0, print_progress=False)
    assert list(ind) == inliers.tolist()
    np.testing.assert_array_equal(np.asarray(cl.colors), colors[inliers])
    np.testing.assert_array_equal(np.asarray(cl.normals), np.tile([0.0, 0.0, 1.0], (len(inliers), 1)))


@pytest.mark.parametrize("kwargs", [dict(nb_neighbors=0, std_ratio=2.0), dict(nb_neighbors=-3, std_ratio=2.0),
                                    dict(nb_neighbors=20, std_ratio=0.0), dict(nb_neighbors=20, std_ratio=-1.0),
                                    dict(nb_neighbors=20, std_ratio=float("nan"))])
def test_statistical_outlier_bad_args(kwargs):
    pcd = o3d.geometry.PointCloud(grid_plane(5))
    with pytest.raises(ValueError):
        pcd.remove_statistical_outlier(**kwargs)


# ---- remove_radius_outlier ----

def test_radius_outlier_keeps_exact_plane_indices():
    pts, inliers = with_outliers(grid_plane(), FAR, FAR_AT)
    pcd = o3d.geometry.PointCloud(pts)
    cl, ind = pcd.remove_radius_outlier(nb_points=2, radius=0.15)
    assert list(ind) == inliers.tolist()
    np.testing.assert_array_equal(np.asarray(cl.points), pts[inliers])


def test_radius_outlier_threshold_counts():
    # 0 and 1 are 0.05 apart, 2 is alone: nb_points=1 keeps the pair, a large nb_points keeps nothing.
    pts = np.array([[0, 0, 0], [0.05, 0, 0], [1, 1, 1]], dtype=float)
    pcd = o3d.geometry.PointCloud(pts)
    cl, ind = pcd.remove_radius_outlier(1, 0.1)
    assert list(ind) == [0, 1]
    assert len(cl) == 2
    cl, ind = pcd.remove_radius_outlier(5, 0.1)
    assert list(ind) == [] and len(cl) == 0
    cl, ind = pcd.remove_radius_outlier(1, 10.0)
    assert list(ind) == [0, 1, 2]


@pytest.mark.parametrize("args", [(0, 0.1), (2, 0.0), (2, -1.0), (2, float("inf"))])
def test_radius_outlier_bad_args(args):
    pcd = o3d.geometry.PointCloud(grid_plane(5))
    with pytest.raises(ValueError):
        pcd.remove_radius_outlier(*args)


def test_outlier_filters_on_empty_cloud_raise():
    pcd = o3d.geometry.PointCloud()
    with pytest.raises(ValueError):
        pcd.remove_statistical_outlier(20, 2.0)
    with pytest.raises(ValueError):
        pcd.remove_radius_outlier(2, 0.1)


# ---- crop ----

def test_axis_aligned_bounding_box_constructs_as_open3d():
    box = o3d.geometry.AxisAlignedBoundingBox(np.array([-1.0, -2, -3]), np.array([1.0, 2, 3]))
    np.testing.assert_array_equal(box.min_bound, [-1, -2, -3])
    np.testing.assert_array_equal(box.get_max_bound(), [1, 2, 3])
    box = o3d.geometry.AxisAlignedBoundingBox(min_bound=[0, 0, 0], max_bound=(1, 1, 1))
    np.testing.assert_array_equal(box.get_extent(), [1, 1, 1])


def test_crop_inclusive_and_invert():
    pts = np.array([
        [0.0, 0.0, 0.0],    # on the min corner: inside
        [1.0, 1.0, 1.0],    # on the max corner: inside
        [0.5, 0.5, 0.5],    # inside
        [1.0 + 1e-9, 0.5, 0.5],  # just outside in x
        [0.5, -1e-9, 0.5],  # just outside in y
        [0.5, 0.5, 2.0],    # outside in z
        [1.0, 0.0, 0.5],    # on two faces: inside
    ])
    pcd = o3d.geometry.PointCloud(pts)
    box = o3d.geometry.AxisAlignedBoundingBox([0, 0, 0], [1, 1, 1])
    inside = pcd.crop(box)
    np.testing.assert_array_equal(np.asarray(inside.points), pts[[0, 1, 2, 6]])
    outside = pcd.crop(box, invert=True)
    np.testing.assert_array_equal(np.asarray(outside.points), pts[[3, 4, 5]])
    assert len(pcd) == len(pts)


def test_crop_with_box_from_cloud_keeps_everything():
    pts = np.random.default_rng(3).normal(size=(200, 3))
    pcd = o3d.geometry.PointCloud(pts)
    pcd.colors = np.random.default_rng(4).uniform(size=(200, 3))
    cropped = pcd.crop(pcd.get_axis_aligned_bounding_box())
    np.testing.assert_array_equal(np.asarray(cropped.points), pts)
    np.testing.assert_array_equal(np.asarray(cropped.colors), np.asarray(pcd.colors))
    assert len(pcd.crop(pcd.get_axis_aligned_bounding_box(), invert=True)) == 0


def test_crop_bad_args():
    pcd = o3d.geometry.PointCloud(grid_plane(5))
    with pytest.raises(TypeError):
        pcd.crop([0, 0, 0])
    with pytest.raises(TypeError):
        pcd.crop(None)
    with pytest.raises(ValueError):  # max < min
        pcd.crop(o3d.geometry.AxisAlignedBoundingBox([1, 1, 1], [0, 0, 0]))
    with pytest.raises(ValueError):
        pcd.crop(o3d.geometry.AxisAlignedBoundingBox([0, 0, np.nan], [1, 1, 1]))


# ---- segment_plane ----

def _plane_with_noise(rng):
    xy = rng.uniform(-1.0, 1.0, size=(300, 2))
    plane = np.column_stack([xy, 0.5 * xy[:, 0] + 0.2])  # z = 0.5 x + 0.2
    off = rng.uniform(-1.0, 1.0, size=(60, 3))
    off[:, 2] = 0.5 * off[:, 0] + 0.2 + rng.choice([-1.0, 1.0], size=60) * rng.uniform(0.2, 1.0, size=60)
    return with_outliers(plane, off, np.sort(rng.choice(360, size=60, replace=False)))


def test_segment_plane_recovers_known_plane(rng):
    pts, inliers = _plane_with_noise(rng)
    pcd = o3d.geometry.PointCloud(pts)
    model, ind = pcd.segment_plane(distance_threshold=0.01, ransac_n=3, num_iterations=1000, seed=7)
    assert isinstance(model, np.ndarray) and model.shape == (4,)
    expected = np.array([0.5, 0.0, -1.0, 0.2]) / np.linalg.norm([0.5, 0.0, -1.0])
    sign = np.sign(np.dot(model[:3], expected[:3]))
    np.testing.assert_allclose(sign * model, expected, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(model[:3]), 1.0, atol=1e-12)
    assert list(ind) == inliers.tolist()


def test_segment_plane_same_seed_same_result(rng):
    pts = np.vstack([grid_plane(15), rng.uniform(-1, 1, size=(100, 3)) + [0, 0, 0.5]])
    pcd = o3d.geometry.PointCloud(pts)
    a = pcd.segment_plane(0.02, 3, 50, seed=123)
    b = pcd.segment_plane(0.02, 3, 50, seed=123)
    np.testing.assert_array_equal(a[0], b[0])
    assert list(a[1]) == list(b[1])
    # default seed (None) still finds the dominant plane
    model, ind = pcd.segment_plane(0.001, 3, 200)
    np.testing.assert_allclose(np.abs(model), [0, 0, 1, 0], atol=1e-9)
    assert set(range(225)) <= set(ind)


@pytest.mark.parametrize("kwargs", [dict(distance_threshold=-0.1), dict(ransac_n=2), dict(num_iterations=0),
                                    dict(probability=0.0), dict(probability=1.5),
                                    dict(distance_threshold=float("nan"))])
def test_segment_plane_bad_args(kwargs):
    pcd = o3d.geometry.PointCloud(grid_plane(5))
    args = dict(distance_threshold=0.01, ransac_n=3, num_iterations=10)
    args.update(kwargs)
    with pytest.raises(ValueError):
        pcd.segment_plane(**args)


def test_segment_plane_too_few_points_raise():
    with pytest.raises(ValueError):
        o3d.geometry.PointCloud(np.eye(3)[:2]).segment_plane(0.01, 3, 10)
    with pytest.raises(ValueError):
        o3d.geometry.PointCloud().segment_plane(0.01, 3, 10)


# ---- cluster_dbscan ----

def _blob(center, n=3, spacing=0.1):
    g = np.arange(n) * spacing
    x, y, z = np.meshgrid(g, g, g, indexing="ij")
    return np.column_stack([x.ravel(), y.ravel(), z.ravel()]) + center


def test_cluster_dbscan_three_blobs_and_noise():
    a, b, c = _blob([0, 0, 0]), _blob([5, 0, 0]), _blob([0, 5, 0])
    noise = np.array([[10.0, 10, 10], [-10.0, 0, 0], [3.0, 3, 3]])
    # order: noise, blob c, blob a, noise, blob b, noise -> labels follow each cluster's lowest index
    pts = np.vstack([noise[:1], c, a, noise[1:2], b, noise[2:]])
    expected = np.concatenate([[-1], np.full(27, 0), np.full(27, 1), [-1], np.full(27, 2), [-1]])
    pcd = o3d.geometry.PointCloud(pts)
    labels = pcd.cluster_dbscan(eps=0.15, min_points=5, print_progress=False)
    assert isinstance(labels, np.ndarray) and labels.dtype == np.int32
    np.testing.assert_array_equal(labels, expected)
    assert labels.max() + 1 == 3
    # Open3D idiom
    labels = np.array(pcd.cluster_dbscan(eps=0.15, min_points=5))
    assert int(labels.max()) == 2 and int((labels < 0).sum()) == 3


def test_cluster_dbscan_min_points_makes_everything_noise():
    pcd = o3d.geometry.PointCloud(_blob([0, 0, 0]))
    np.testing.assert_array_equal(pcd.cluster_dbscan(0.15, 100), np.full(27, -1, dtype=np.int32))
    np.testing.assert_array_equal(pcd.cluster_dbscan(10.0, 1), np.zeros(27, dtype=np.int32))


@pytest.mark.parametrize("args", [(0.0, 5), (-1.0, 5), (float("nan"), 5), (0.1, -1)])
def test_cluster_dbscan_bad_args(args):
    pcd = o3d.geometry.PointCloud(_blob([0, 0, 0]))
    with pytest.raises(ValueError):
        pcd.cluster_dbscan(*args)


# ---- statistics ----

def test_mean_and_covariance_match_numpy(rng):
    pts = rng.normal(size=(500, 3)) @ np.array([[2.0, 0, 0], [0.5, 1.0, 0], [0.1, -0.3, 0.2]]) + [1, -2, 3]
    pcd = o3d.geometry.PointCloud(pts)
    mean, cov = pcd.compute_mean_and_covariance()
    assert mean.shape == (3,) and cov.shape == (3, 3)
    np.testing.assert_allclose(mean, pts.mean(axis=0), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(cov, np.cov(pts.T, bias=True), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(cov, cov.T, atol=0)


def test_mean_and_covariance_small_exact():
    pcd = o3d.geometry.PointCloud(np.array([[0.0, 0, 0], [2.0, 0, 0]]))
    mean, cov = pcd.compute_mean_and_covariance()
    np.testing.assert_allclose(mean, [1, 0, 0])
    np.testing.assert_allclose(cov, [[1, 0, 0], [0, 0, 0], [0, 0, 0]])


def test_mahalanobis_matches_numpy(rng):
    pts = rng.normal(size=(400, 3)) @ np.array([[3.0, 0, 0], [1.0, 0.5, 0], [0.2, 0.1, 0.7]]) + [5, 0, -1]
    pcd = o3d.geometry.PointCloud(pts)
    d = pcd.compute_mahalanobis_distance()
    assert isinstance(d, np.ndarray) and d.shape == (400,) and d.dtype == np.float64
    mu = pts.mean(axis=0)
    inv = np.linalg.inv(np.cov(pts.T, bias=True))
    diff = pts - mu
    expected = np.sqrt(np.einsum("ij,jk,ik->i", diff, inv, diff))
    np.testing.assert_allclose(d, expected, rtol=1e-9, atol=1e-12)
    # the squared distances of N points average to the dimension (3) with the biased covariance
    assert np.mean(d ** 2) == pytest.approx(3.0, rel=1e-9)


def test_statistics_on_empty_cloud_raise():
    pcd = o3d.geometry.PointCloud()
    with pytest.raises(ValueError):
        pcd.compute_mean_and_covariance()
    with pytest.raises(ValueError):
        pcd.compute_mahalanobis_distance()
    with pytest.raises(ValueError):
        pcd.cluster_dbscan(0.1, 1)
    with pytest.raises(ValueError):
        pcd.crop(o3d.geometry.AxisAlignedBoundingBox([0, 0, 0], [1, 1, 1]))


def test_tools_run_concurrently_on_one_cloud():
    # the long calls release the GIL and share the cloud's read lock: threads agree with a serial run
    pts, inliers = with_outliers(grid_plane(30), FAR, [0, 500, 902])
    pcd = o3d.geometry.PointCloud(pts)
    expected = pcd.cluster_dbscan(0.15, 3)
    results, errors = [], []

    def work():
        try:
            for _ in range(5):
                _, ind = pcd.remove_statistical_outlier(20, 2.0)
                results.append((list(ind) == inliers.tolist(),
                                np.array_equal(pcd.cluster_dbscan(0.15, 3), expected)))
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert len(results) == 20 and all(a and b for a, b in results)


# ---- Open3D tutorial calls, unchanged ----

def test_open3d_tutorial_calls_run_unchanged(rng):
    xy = rng.uniform(-1.0, 1.0, size=(2000, 2))
    floor = np.column_stack([xy, rng.normal(scale=0.002, size=2000)])
    box = rng.uniform([0.2, 0.2, 0.1], [0.4, 0.4, 0.3], size=(300, 3))
    stray = rng.uniform(-5, 5, size=(10, 3)) + [0, 0, 8]
    pcd = o3d.geometry.PointCloud()
    pcd.points = o3d.utility.Vector3dVector(np.vstack([floor, box, stray]))

    voxel_down_pcd = pcd.voxel_down_sample(voxel_size=0.02)
    cl, ind = voxel_down_pcd.remove_statistical_outlier(nb_neighbors=20, std_ratio=2.0)
    inlier_cloud = voxel_down_pcd.select_by_index(ind)
    outlier_cloud = voxel_down_pcd.select_by_index(ind, invert=True)
    assert len(inlier_cloud) + len(outlier_cloud) == len(voxel_down_pcd)
    assert len(cl) == len(inlier_cloud)
    cl, ind = voxel_down_pcd.remove_radius_outlier(nb_points=16, radius=0.05)
    assert 0 < len(ind) < len(voxel_down_pcd)

    plane_model, inliers = pcd.segment_plane(distance_threshold=0.01, ransac_n=3, num_iterations=1000)
    [a, b, c, d] = plane_model
    print(f"Plane equation: {a:.2f}x + {b:.2f}y + {c:.2f}z + {d:.2f} = 0")
    assert abs(c) > 0.999 and abs(d) < 0.01
    inlier_cloud = pcd.select_by_index(inliers)
    inlier_cloud.paint_uniform_color([1.0, 0, 0])
    outlier_cloud = pcd.select_by_index(inliers, invert=True)
    assert len(inlier_cloud) >= 1900 and len(outlier_cloud) >= 300

    with o3d.utility.VerbosityContextManager(o3d.utility.VerbosityLevel.Debug) as cm:
        labels = np.array(outlier_cloud.cluster_dbscan(eps=0.1, min_points=10, print_progress=True))
    max_label = labels.max()
    print(f"point cloud has {max_label + 1} clusters")
    assert max_label >= 0

    bbox = o3d.geometry.AxisAlignedBoundingBox(min_bound=(-1, -1, -1), max_bound=(1, 1, 1))
    cropped = pcd.crop(bbox)
    assert len(cropped) == 2300
    mean, cov = pcd.compute_mean_and_covariance()
    assert mean.shape == (3,) and cov.shape == (3, 3)
    assert pcd.compute_mahalanobis_distance().shape == (len(pcd.points),)


# ---- remove_duplicated_points ----

def test_remove_duplicated_points_keeps_first_occurrences():
    pts = np.array([[0.0, 0, 0], [1, 0, 0], [0, 0, 0], [0, 1, 0], [1, 0, 0], [0, 1, 1e-12]])
    pcd = o3d.geometry.PointCloud(pts)
    pcd.normals = np.arange(18, dtype=float).reshape(6, 3)
    pcd.colors = np.linspace(0, 1, 18).reshape(6, 3)
    assert pcd.remove_duplicated_points() is pcd  # Open3D returns the cloud itself
    keep = [0, 1, 3, 5]  # exact repeats only: 1e-12 apart is another point
    np.testing.assert_array_equal(np.asarray(pcd.points), pts[keep])
    np.testing.assert_array_equal(np.asarray(pcd.normals), np.arange(18, dtype=float).reshape(6, 3)[keep])
    np.testing.assert_array_equal(np.asarray(pcd.colors), np.linspace(0, 1, 18).reshape(6, 3)[keep])


def test_remove_duplicated_points_without_repeats_and_views():
    pts = grid_plane(5)
    pcd = o3d.geometry.PointCloud(np.vstack([pts, pts]))
    view = np.asarray(pcd.points)
    pcd.remove_duplicated_points()
    np.testing.assert_array_equal(np.asarray(pcd.points), pts)
    assert view.shape == (50, 3)  # an old view keeps the old data (copy-on-write)
    assert len(o3d.geometry.PointCloud().remove_duplicated_points().points) == 0
    assert len(pcd.remove_duplicated_points().points) == 25
