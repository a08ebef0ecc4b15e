"""Global registration from Python: correspondence checkers, RANSAC (features or correspondences), FGR,
seeds and thread counts, progress and cancellation, and bad arguments.

cloud_bin_0 and cloud_bin_1 are aligned with each other to about 0.4 deg / 17 mm; the source is cloud_bin_0
moved by a known large motion, so a registration must find about the inverse of that motion."""
import numpy as np
import pytest

import o3d
from o3d.pipelines import registration as reg

FEATURE_DIR = "open3d/Feature"


def motion():
    """75 degrees about (0.3, -1, 0.5) through the origin, then (0.4, -0.2, 0.3)."""
    axis = np.array([0.3, -1.0, 0.5])
    axis /= np.linalg.norm(axis)
    a = np.deg2rad(75.0)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    m = np.eye(4)
    m[:3, :3] = np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k
    m[:3, 3] = [0.4, -0.2, 0.3]
    return m


def errors(transformation, truth, points):
    """(rotation error in degrees, mean displacement in metres of `points` under the two transforms)."""
    d = np.linalg.inv(truth) @ np.asarray(transformation)
    angle = np.degrees(np.arccos(np.clip((np.trace(d[:3, :3]) - 1.0) / 2.0, -1.0, 1.0)))
    a = points @ np.asarray(transformation)[:3, :3].T + np.asarray(transformation)[:3, 3]
    b = points @ truth[:3, :3].T + truth[:3, 3]
    return angle, float(np.linalg.norm(a - b, axis=1).mean())


@pytest.fixture
def scene(data_file):
    source = o3d.io.read_point_cloud(data_file(f"{FEATURE_DIR}/cloud_bin_0.pcd"))
    target = o3d.io.read_point_cloud(data_file(f"{FEATURE_DIR}/cloud_bin_1.pcd"))
    m = motion()
    source.transform(m)
    fs = o3d.io.read_feature(data_file(f"{FEATURE_DIR}/cloud_bin_0.fpfh.bin"))  # FPFH: invariant to the motion
    ft = o3d.io.read_feature(data_file(f"{FEATURE_DIR}/cloud_bin_1.fpfh.bin"))
    return source, target, fs, ft, np.linalg.inv(m)


CHECKERS = [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(0.075)]
CRITERIA = reg.RANSACConvergenceCriteria(100000, 0.999)


def ransac(scene, **extras):
    source, target, fs, ft, _ = scene
    return reg.registration_ransac_based_on_feature_matching(
        source, target, fs, ft, True, 0.075, reg.TransformationEstimationPointToPoint(False), 3, CHECKERS, CRITERIA,
        **extras)


def assert_recovered(result, scene, degrees=3.0, metres=0.05):
    source, _, _, _, truth = scene
    angle, shift = errors(result.transformation, truth, np.asarray(source.points))
    assert angle < degrees and shift < metres, (angle, shift)


# ---- defaults, attributes

def test_defaults_and_attributes():
    c = reg.RANSACConvergenceCriteria()
    assert (c.max_iteration, c.confidence) == (100000, 0.999)
    assert repr(c) == "RANSACConvergenceCriteria(max_iteration=100000, confidence=9.990000e-01)"
    e = reg.CorrespondenceCheckerBasedOnEdgeLength()
    assert e.similarity_threshold == 0.9 and e.require_pointcloud_alignment_ is False
    d = reg.CorrespondenceCheckerBasedOnDistance(0.1)
    assert d.distance_threshold == 0.1 and d.require_pointcloud_alignment_ is True
    n = reg.CorrespondenceCheckerBasedOnNormal(normal_angle_threshold=0.5)
    n.normal_angle_threshold = 0.25
    assert n.normal_angle_threshold == 0.25 and isinstance(n, reg.CorrespondenceChecker)
    assert repr(d) == "CorrespondenceCheckerBasedOnDistance with distance_threshold=0.100000"
    o = reg.FastGlobalRegistrationOption()
    assert (o.division_factor, o.use_absolute_scale, o.maximum_correspondence_distance, o.iteration_number,
            o.tuple_scale, o.maximum_tuple_count, o.tuple_test, o.seed) == (1.4, False, 0.025, 64, 0.95, 1000, True, None)
    assert o.decrease_mu is False  # Open3D 0.20's Python constructor default
    o.seed = 5
    assert reg.FastGlobalRegistrationOption(o).seed == 5


# ---- checkers

def test_checkers_accept_true_and_reject_false_hypotheses(scene):
    source, target, fs, ft, truth = scene
    assert source.has_normals() and target.has_normals()
    # pairs that really correspond: source points whose nearest target point under the true motion is close,
    # with agreeing normals; three far apart
    moved = np.asarray(source.points) @ truth[:3, :3].T + truth[:3, 3]
    moved_normals = np.asarray(source.normals) @ truth[:3, :3].T
    _, nearest, d2 = o3d.geometry.KDTreeFlann(target).search_knn(moved, 1)
    agree = np.einsum("ij,ij->i", moved_normals, np.asarray(target.normals)[nearest]) > 0.95
    good = np.flatnonzero((d2 < 0.02 ** 2) & agree)
    corres = [(int(i), int(nearest[i])) for i in (good[0], good[len(good) // 2], good[-1])]
    distance = reg.CorrespondenceCheckerBasedOnDistance(0.05)
    assert distance.Check(source, target, corres, truth)
    assert not distance.Check(source, target, corres, np.identity(4))
    edge = reg.CorrespondenceCheckerBasedOnEdgeLength(0.9)
    assert edge.Check(source, target, o3d.utility.Vector2iVector(np.array(corres)), np.identity(4))  # no alignment needed
    assert not edge.Check(source, target, [(10, 0), (900, 1), (2500, 2)], np.identity(4))
    normal = reg.CorrespondenceCheckerBasedOnNormal(np.deg2rad(30.0))
    assert normal.Check(source, target, corres, truth)


# ---- RANSAC

def test_ransac_on_features_recovers_the_motion(scene):
    result = ransac(scene, seed=1)
    assert_recovered(result, scene)
    assert result.fitness > 0.3 and len(result.correspondence_set) > 0


def test_ransac_same_seed_same_result_on_any_thread_count(scene):
    one = ransac(scene, seed=123, num_threads=1)
    two = ransac(scene, seed=123, num_threads=2)
    np.testing.assert_array_equal(one.transformation, two.transformation)
    assert one.fitness == two.fitness and one.inlier_rmse == two.inlier_rmse


def test_global_seed_reproduces(scene):
    o3d.utility.random.seed(2024)
    first = ransac(scene)
    o3d.utility.random.seed(2024)
    again = ransac(scene)
    np.testing.assert_array_equal(first.transformation, again.transformation)
    from o3d.utility import random  # also importable as a module, as Open3D's

    random.seed(2024)
    np.testing.assert_array_equal(ransac(scene).transformation, first.transformation)


def test_ransac_on_correspondences(scene):
    source, target, fs, ft, _ = scene
    corres = reg.correspondences_from_features(fs, ft, True)
    result = reg.registration_ransac_based_on_correspondence(source, target, corres, 0.075,
                                                             reg.TransformationEstimationPointToPoint(False), 3,
                                                             CHECKERS, CRITERIA, seed=7)
    assert_recovered(result, scene)
    same = reg.registration_ransac_based_on_correspondence(source, target, np.asarray(corres), 0.075, seed=7,
                                                           checkers=CHECKERS, criteria=CRITERIA)
    np.testing.assert_array_equal(same.transformation, result.transformation)  # ndarray == Vector2iVector


def test_ransac_progress_cancel_and_errors_from_callback(scene, capsys):
    seen = []
    ransac(scene, seed=3, callback=lambda f: seen.append(f))
    assert seen and all(0.0 <= f <= 1.0 for f in seen) and seen == sorted(seen)
    calls = []
    with pytest.raises(o3d.CancelledError):
        ransac(scene, seed=3, callback=lambda f: calls.append(f) or True)
    assert len(calls) == 1

    class Stop(Exception):
        pass

    def boom(fraction):
        raise Stop()

    with pytest.raises(Stop):
        ransac(scene, seed=3, callback=boom)
    ransac(scene, seed=3, print_progress=True)
    assert "RANSAC" in capsys.readouterr().err


# ---- FGR

def test_fgr_recovers_the_motion(scene):
    source, target, fs, ft, _ = scene
    option = reg.FastGlobalRegistrationOption(maximum_correspondence_distance=0.025, decrease_mu=True, seed=11)
    result = reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, option)
    assert_recovered(result, scene, metres=0.06)
    corres = reg.correspondences_from_features(fs, ft, True)
    on_corres = reg.registration_fgr_based_on_correspondence(source, target, corres, option)
    assert_recovered(on_corres, scene, metres=0.06)


def test_fgr_seed_and_threads(scene):
    source, target, fs, ft, _ = scene
    option = reg.FastGlobalRegistrationOption(maximum_correspondence_distance=0.025, decrease_mu=True)
    one = reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, option, seed=5, num_threads=1)
    two = reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, option, seed=5, num_threads=2)
    np.testing.assert_array_equal(one.transformation, two.transformation)
    option.seed = 5  # the option's seed is the same as the call's
    three = reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, option)
    np.testing.assert_array_equal(one.transformation, three.transformation)


def test_fgr_progress_and_cancel(scene, capsys):
    source, target, fs, ft, _ = scene
    seen = []
    reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, seed=1, callback=seen.append)
    assert seen and seen[-1] <= 1.0
    with pytest.raises(o3d.CancelledError):
        reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, seed=1, callback=lambda f: True)
    reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, seed=1, print_progress=True)
    assert "FGR" in capsys.readouterr().err


# ---- bad input

def test_bad_arguments_raise(scene):
    source, target, fs, ft, _ = scene
    nan = float("nan")
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, nan)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075,
                                                          checkers=[reg.CorrespondenceCheckerBasedOnDistance(nan)])
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075, ransac_n=2)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075,
                                                          criteria=reg.RANSACConvergenceCriteria(10, 1.5))
    short = reg.Feature()
    short.data = np.zeros((10, len(target.points)))
    with pytest.raises(o3d.InvalidArgumentError):  # mismatched feature dimensions
        reg.registration_ransac_based_on_feature_matching(source, target, fs, short, False, 0.075)
    with pytest.raises(o3d.InvalidArgumentError):  # one descriptor per point
        reg.registration_ransac_based_on_feature_matching(source, target, ft, ft, False, 0.075)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_ransac_based_on_correspondence(source, target, [(0, 10 ** 6), (1, 2), (3, 4)], 0.075)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_ransac_based_on_correspondence(source, target, np.zeros((5, 2)), 0.075)  # float pairs
    with pytest.raises(ValueError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075, checkers=[1])
    with pytest.raises(ValueError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075,
                                                          estimation_method="point")
    with pytest.raises(o3d.InvalidArgumentError):  # RANSAC has no robust kernel: refused, not dropped
        reg.registration_ransac_based_on_feature_matching(
            source, target, fs, ft, False, 0.075, reg.TransformationEstimationPointToPlane(reg.TukeyLoss(k=0.1)))
    with pytest.raises(ValueError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075, seed="x")
    with pytest.raises(TypeError):
        reg.registration_ransac_based_on_feature_matching(source, target, fs, ft, False, 0.075, callback=3)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_fgr_based_on_feature_matching(
            source, target, fs, ft, reg.FastGlobalRegistrationOption(maximum_correspondence_distance=nan))
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_fgr_based_on_feature_matching(source, target, fs, ft,
                                                       reg.FastGlobalRegistrationOption(division_factor=0.5))
    with pytest.raises(ValueError):
        reg.registration_fgr_based_on_feature_matching(source, target, fs, ft, option=reg.RANSACConvergenceCriteria())
    with pytest.raises(o3d.InvalidArgumentError):
        reg.CorrespondenceCheckerBasedOnDistance(nan).Check(source, target, [(0, 0)], np.identity(4))


def test_python_wrapper_defaults_match_open3d_and_the_c_library():
    import inspect

    ransac = inspect.signature(reg.registration_ransac_based_on_feature_matching).parameters
    assert ransac["ransac_n"].default == 3 and ransac["num_threads"].default == 0
    assert inspect.signature(reg.registration_ransac_based_on_correspondence).parameters["ransac_n"].default == 3
    assert inspect.signature(reg.registration_icp).parameters["num_threads"].default == 0
    assert inspect.signature(reg.global_optimization).parameters["num_threads"].default == 0
    edge = reg.PoseGraphEdge()
    assert (edge.uncertain, edge.confidence) == (False, 1.0)
    np.testing.assert_array_equal(edge.transformation, np.identity(4))
    np.testing.assert_array_equal(edge.information, np.identity(6))
