import numpy as np
import pytest

import o3d
from o3d.pipelines import registration as reg


def rigid(deg, t):
    a = np.deg2rad(deg)
    T = np.eye(4)
    T[:3, :3] = [[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]]
    T[:3, 3] = t
    return T


@pytest.fixture
def pair(rng):
    """A non-symmetric synthetic shape and its copy moved by a known transform."""
    u = rng.uniform(size=(800, 2))
    pts = np.column_stack([u[:, 0] * 2.0, u[:, 1], 0.3 * np.sin(3 * u[:, 0]) + 0.2 * u[:, 1] ** 2])
    T = rigid(6.0, [0.05, -0.03, 0.02])
    source = o3d.geometry.PointCloud(pts)
    target = o3d.geometry.PointCloud(pts @ T[:3, :3].T + T[:3, 3])
    return source, target, T


def test_point_to_point_recovers_transform(pair):
    source, target, T = pair
    result = reg.registration_icp(source, target, 0.3, np.identity(4),
                                  reg.TransformationEstimationPointToPoint(),
                                  reg.ICPConvergenceCriteria(max_iteration=100))
    assert isinstance(result, reg.RegistrationResult)
    assert result.transformation.shape == (4, 4)
    np.testing.assert_allclose(result.transformation, T, atol=1e-4)
    assert result.fitness == pytest.approx(1.0)
    assert result.inlier_rmse < 1e-4
    cs = np.asarray(result.correspondence_set)
    assert cs.shape == (800, 2)
    assert np.mean(cs[:, 0] == cs[:, 1]) > 0.95


def test_point_to_plane_recovers_transform(pair):
    source, target, T = pair
    target.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(15))
    result = reg.registration_icp(source, target, 0.3, estimation_method=reg.TransformationEstimationPointToPlane(),
                                  criteria=reg.ICPConvergenceCriteria(max_iteration=100))
    np.testing.assert_allclose(result.transformation, T, atol=1e-3)


def test_scaling_estimation(pair):
    source, _, _ = pair
    # Scaled about the centroid: scaling about the origin moves points up to 0.2 away, and from
    # identity both Open3D 0.20 and o3d then settle in the same local minimum for some samples.
    pts = np.asarray(source.points)
    c = pts.mean(axis=0)
    target = o3d.geometry.PointCloud((pts - c) * 1.1 + c)
    result = reg.registration_icp(source, target, 0.5, estimation_method=reg.TransformationEstimationPointToPoint(True),
                                  criteria=reg.ICPConvergenceCriteria(max_iteration=200))
    np.testing.assert_allclose(np.linalg.det(result.transformation[:3, :3]), 1.1 ** 3, rtol=1e-3)


def test_evaluate_registration(pair):
    source, target, T = pair
    at_truth = reg.evaluate_registration(source, target, 0.01, T)
    assert at_truth.fitness == pytest.approx(1.0)
    assert at_truth.inlier_rmse < 1e-9
    np.testing.assert_allclose(at_truth.transformation, T)
    far = reg.evaluate_registration(source, target, 1e-6)
    assert far.fitness < 0.05


def test_information_matrix(pair):
    source, target, T = pair
    info = reg.get_information_matrix_from_point_clouds(source, target, 0.01, T)
    assert info.shape == (6, 6)
    np.testing.assert_allclose(info, info.T)
    assert info[3, 3] == pytest.approx(800.0)  # translation block = identity per correspondence
    assert np.all(np.linalg.eigvalsh(info) > -1e-9)


def test_criteria_and_estimation_attributes():
    c = reg.ICPConvergenceCriteria(relative_fitness=1e-3, relative_rmse=1e-4, max_iteration=7)
    assert (c.relative_fitness, c.relative_rmse, c.max_iteration) == (1e-3, 1e-4, 7)
    c.max_iteration = 9
    assert c.max_iteration == 9
    d = reg.ICPConvergenceCriteria()
    assert (d.relative_fitness, d.relative_rmse, d.max_iteration) == (1e-6, 1e-6, 30)
    assert reg.TransformationEstimationPointToPoint().with_scaling is False
    r = reg.RegistrationResult()
    np.testing.assert_array_equal(r.transformation, np.eye(4))


def test_callback_sees_progress_and_can_cancel(pair):
    source, target, _ = pair
    seen = []
    strict = reg.ICPConvergenceCriteria(relative_fitness=0, relative_rmse=0, max_iteration=20)
    reg.registration_icp(source, target, 0.3, criteria=strict, callback=lambda f: seen.append(f))
    assert seen and all(0.0 <= f <= 1.0 for f in seen)
    assert seen == sorted(seen)
    calls = []
    with pytest.raises(o3d.CancelledError):
        reg.registration_icp(source, target, 0.3, criteria=strict, callback=lambda f: calls.append(f) or True)
    assert len(calls) == 1


def test_callback_exception_propagates(pair):
    source, target, _ = pair

    class Stop(Exception):
        pass

    def boom(fraction):
        raise Stop("stop here")

    with pytest.raises(Stop):
        reg.registration_icp(source, target, 0.3, callback=boom)


def test_print_progress_writes_a_bar(pair, capsys):
    source, target, _ = pair
    reg.registration_icp(source, target, 0.3, print_progress=True)
    err = capsys.readouterr().err
    assert "ICP" in err and "%" in err


def test_bad_arguments(pair):
    source, target, _ = pair
    with pytest.raises(ValueError):
        reg.registration_icp(source, target, 0.3, init=np.eye(3))
    with pytest.raises(ValueError):
        reg.registration_icp(source, target, float("nan"))
    with pytest.raises(ValueError):
        reg.registration_icp(source, target, 0.3, estimation_method="point")
    with pytest.raises(ValueError):  # point-to-plane needs target normals
        reg.registration_icp(source, target, 0.3, estimation_method=reg.TransformationEstimationPointToPlane())
