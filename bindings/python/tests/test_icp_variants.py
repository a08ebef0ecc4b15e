"""Colored, generalized and symmetric ICP, robust kernels, and registration_icp with every estimation.
Kernel weights: Open3D 0.20's RobustKernel.weight (tools/reference/record_python_registration.py, kernel.*)."""
import copy

import numpy as np
import pytest

import o3d
from o3d.pipelines import registration as reg

CRITERIA = reg.ICPConvergenceCriteria(relative_fitness=1e-9, relative_rmse=1e-9, max_iteration=60)


def small_motion(deg=3.0, axis=(0.2, 1.0, -0.4), t=(0.03, -0.02, 0.015)):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    a = np.deg2rad(deg)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    m = np.eye(4)
    m[:3, :3] = np.eye(3) + np.sin(a) * k + (1 - np.cos(a)) * k @ k
    m[:3, 3] = t
    return m


def moved_copy(pcd, m):
    out = copy.deepcopy(pcd)
    out.transform(m)
    return out


@pytest.fixture
def fragment(data_file):
    """fragment.pcd (colours and normals), on a 3 cm grid."""
    return o3d.io.read_point_cloud(data_file("open3d/fragment.pcd")).voxel_down_sample(0.03)


@pytest.fixture
def scan(data_file):
    return o3d.io.read_point_cloud(data_file("open3d/Feature/cloud_bin_0.pcd"))


# ---- estimations

def test_estimation_defaults_and_kernels():
    colored = reg.TransformationEstimationForColoredICP()
    assert colored.lambda_geometric == 0.968 and isinstance(colored.kernel, reg.L2Loss)
    assert repr(colored) == "TransformationEstimationForColoredICP(lambda_geometric=0.968)"
    gicp = reg.TransformationEstimationForGeneralizedICP()
    assert gicp.epsilon == 0.001 and repr(gicp) == "TransformationEstimationForGeneralizedICP(epsilon=0.001)"
    assert repr(reg.TransformationEstimationSymmetric()) == "TransformationEstimationSymmetric"
    tukey = reg.TukeyLoss(k=0.1)
    plane = reg.TransformationEstimationPointToPlane(tukey)
    assert plane.kernel is tukey  # shared, as Open3D's shared_ptr
    plane.kernel.k = 0.2
    assert tukey.k == 0.2 and repr(plane.kernel) == "RobustKernel::TukeyLoss with k=0.200000"
    plane.kernel = reg.HuberLoss(0.5)
    assert isinstance(plane.kernel, reg.HuberLoss)
    assert reg.TransformationEstimationForColoredICP(0.5, reg.CauchyLoss(1.0)).lambda_geometric == 0.5
    assert isinstance(reg.TransformationEstimationForColoredICP(reg.GMLoss(1.0)).kernel, reg.GMLoss)
    assert isinstance(reg.TransformationEstimationForGeneralizedICP(kernel=reg.L1Loss()).kernel, reg.L1Loss)
    with pytest.raises(TypeError):
        reg.RobustKernel()  # abstract, as Open3D's
    with pytest.raises(ValueError):
        reg.TransformationEstimationPointToPlane(kernel="tukey")


def test_kernel_weights_match_open3d():
    residuals = [0.3, 1.0, 2.5]
    expected = {  # record_python_registration.py: kernel.*
        reg.L2Loss(): [1.0, 1.0, 1.0],
        reg.L1Loss(): [3.3333333333333335, 1.0, 0.4],
        reg.HuberLoss(k=1.0): [1.0, 1.0, 0.4],
        reg.CauchyLoss(k=0.5): [0.7352941176470589, 0.2, 0.038461538461538464],
        reg.GMLoss(k=0.5): [1.4363688595231257, 0.2222222222222222, 0.010973936899862825],
        reg.TukeyLoss(k=2.0): [0.9555062500000001, 0.5625, 0.0],
    }
    for kernel, weights in expected.items():
        np.testing.assert_allclose([kernel.weight(r) for r in residuals], weights, rtol=1e-12, err_msg=repr(kernel))
    assert reg.HuberLoss(2.0).weight(-3.0) == pytest.approx(2.0 / 3.0)  # |r|
    with pytest.raises(o3d.InvalidArgumentError):
        reg.TukeyLoss(k=float("nan")).weight(0.1)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.HuberLoss(k=-1.0).weight(0.1)


# ---- the ICP variants recover small known transforms

def test_colored_icp_recovers_a_small_transform(fragment):
    m = small_motion()
    source = moved_copy(fragment, m)
    result = reg.registration_colored_icp(source, fragment, 0.05, np.identity(4),
                                          reg.TransformationEstimationForColoredICP(), CRITERIA)
    np.testing.assert_allclose(result.transformation, np.linalg.inv(m), atol=2e-4)
    assert result.fitness > 0.99
    same = reg.registration_icp(source, fragment, 0.05, np.identity(4), reg.TransformationEstimationForColoredICP(),
                                CRITERIA)
    np.testing.assert_array_equal(same.transformation, result.transformation)


def test_colored_icp_uses_color(fragment):
    """lambda_geometric=0 leaves only the photometric term; it must still converge to the truth."""
    m = small_motion(deg=1.0, t=(0.01, 0.0, -0.01))
    source = moved_copy(fragment, m)
    result = reg.registration_colored_icp(source, fragment, 0.05, None,
                                          reg.TransformationEstimationForColoredICP(lambda_geometric=0.0), CRITERIA)
    np.testing.assert_allclose(result.transformation, np.linalg.inv(m), atol=5e-3)


def test_generalized_icp_recovers_a_small_transform_on_a_plain_scan(scan):
    plain = o3d.geometry.PointCloud(np.asarray(scan.points))  # no normals, no colours
    m = small_motion()
    source = moved_copy(plain, m)
    result = reg.registration_generalized_icp(source, plain, 0.1, np.identity(4),
                                              reg.TransformationEstimationForGeneralizedICP(), CRITERIA)
    np.testing.assert_allclose(result.transformation, np.linalg.inv(m), atol=1e-3)
    assert result.fitness > 0.99


def test_symmetric_icp_recovers_a_small_transform(scan):
    m = small_motion(deg=4.0)
    source = moved_copy(scan, m)  # normals move with the points
    result = reg.registration_symmetric_icp(source, scan, 0.1, np.identity(4),
                                            reg.TransformationEstimationSymmetric(), CRITERIA)
    np.testing.assert_allclose(result.transformation, np.linalg.inv(m), atol=1e-3)
    assert isinstance(reg.registration_symmetric_icp(source, scan, 0.1).transformation, np.ndarray)


@pytest.mark.parametrize("kernel", [reg.TukeyLoss(k=0.03), reg.HuberLoss(k=0.01), reg.CauchyLoss(k=0.01),
                                    reg.GMLoss(k=0.01)], ids=repr)
def test_robust_kernels_keep_point_to_plane_on_target_with_30_percent_outliers(scan, rng, kernel):
    m = small_motion(deg=2.0, t=(0.02, 0.01, -0.01))
    pts = np.asarray(scan.points)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    outliers = rng.uniform(lo, hi, size=(int(0.3 * len(pts) / 0.7), 3))
    source = o3d.geometry.PointCloud(np.vstack([pts, outliers]) @ m[:3, :3].T + m[:3, 3])
    robust = reg.registration_icp(source, scan, 0.1, np.identity(4), reg.TransformationEstimationPointToPlane(kernel),
                                  CRITERIA)
    np.testing.assert_allclose(robust.transformation, np.linalg.inv(m), atol=2e-3)


def test_icp_variants_cancel_and_report_progress(scan, capsys):
    source = moved_copy(scan, small_motion())
    calls = []
    with pytest.raises(o3d.CancelledError):
        reg.registration_generalized_icp(source, scan, 0.1, callback=lambda f: calls.append(f) or True)
    assert len(calls) == 1
    reg.registration_symmetric_icp(source, scan, 0.1, print_progress=True)
    assert "ICP" in capsys.readouterr().err


def test_icp_variant_errors(scan, fragment):
    bare = o3d.geometry.PointCloud(np.asarray(scan.points))
    with pytest.raises(o3d.InvalidArgumentError):  # colored ICP needs colours
        reg.registration_colored_icp(bare, bare, 0.1)
    with pytest.raises(o3d.InvalidArgumentError):  # symmetric ICP needs normals on both clouds
        reg.registration_symmetric_icp(bare, scan, 0.1)
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_colored_icp(fragment, fragment, 0.1,
                                     estimation_method=reg.TransformationEstimationForColoredICP(lambda_geometric=1.5))
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_generalized_icp(scan, scan, 0.1,
                                         estimation_method=reg.TransformationEstimationForGeneralizedICP(epsilon=-1.0))
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_icp(scan, scan, 0.1,
                             estimation_method=reg.TransformationEstimationPointToPlane(reg.TukeyLoss(k=float("nan"))))
    with pytest.raises(o3d.InvalidArgumentError):  # the variant functions take their own estimation only
        reg.registration_colored_icp(fragment, fragment, 0.1,
                                     estimation_method=reg.TransformationEstimationPointToPlane())
    with pytest.raises(o3d.InvalidArgumentError):
        reg.registration_generalized_icp(scan, scan, float("nan"))
