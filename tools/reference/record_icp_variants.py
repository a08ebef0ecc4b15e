#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's colored, generalized and symmetric ICP and robust-kernel ICP on the cloud_bin pair, for
tests/core/icp_variants_reference_test.cpp
(and the kernel weights of tests/core/robust_kernel_test.cpp).

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/refvenv && /tmp/refvenv/bin/pip install open3d numpy
    /tmp/refvenv/bin/python tools/reference/record_icp_variants.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.

The clouds are used as stored (cloud_bin_0: 3903 points, cloud_bin_1: 3458, both with colors and normals),
source cloud_bin_0, target cloud_bin_1, threshold 0.02, init identity, default ICPConvergenceCriteria.
"""
import os
import sys

import numpy as np
import open3d as o3d

reg = o3d.pipelines.registration
THRESHOLD = 0.02
TRANS_INIT = np.identity(4)


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def show(name, result, source, target):
    t = np.asarray(result.transformation)
    evaluated = reg.evaluate_registration(source, target, THRESHOLD, t)
    print(f"// {name}: fitness, inlier_rmse, correspondences, transformation (row-major)")
    print(f"// (evaluate_registration at the result: fitness {evaluated.fitness!r}, rmse {evaluated.inlier_rmse!r})")
    print(f"constexpr double k{name}Fitness = {result.fitness!r};")
    print(f"constexpr double k{name}Rmse = {result.inlier_rmse!r};")
    print(f"constexpr size_t k{name}Pairs = {len(result.correspondence_set)};")
    print(f"constexpr double k{name}Transformation[16] = {{{', '.join(repr(float(v)) for v in t.ravel())}}};")


def plane_covariances(cloud, epsilon):
    """epsilon n n^T + (I - n n^T) per normal: the covariance Open3D builds from a unit normal n."""
    n = np.asarray(cloud.normals)
    return np.eye(3)[None, :, :] - (1.0 - epsilon) * n[:, :, None] * n[:, None, :]


def main():
    feature = os.path.join(data_root(), "open3d", "Feature")
    source = o3d.io.read_point_cloud(os.path.join(feature, "cloud_bin_0.pcd"))
    target = o3d.io.read_point_cloud(os.path.join(feature, "cloud_bin_1.pcd"))
    print(f"// Open3D {o3d.__version__}, numpy {np.__version__}; source {len(source.points)} points, "
          f"target {len(target.points)} points, threshold {THRESHOLD}, init = identity")

    show("Colored", reg.registration_colored_icp(source, target, THRESHOLD, TRANS_INIT), source, target)
    show("ColoredHalf", reg.registration_colored_icp(
        source, target, THRESHOLD, TRANS_INIT, reg.TransformationEstimationForColoredICP(lambda_geometric=0.5)),
        source, target)
    show("ColoredHuber", reg.registration_colored_icp(
        source, target, THRESHOLD, TRANS_INIT, reg.TransformationEstimationForColoredICP(kernel=reg.HuberLoss(k=0.005))),
        source, target)

    # From the stored normals (Open3D's rotation of diag(epsilon, 1, 1) onto each normal).
    show("GicpNormals", reg.registration_generalized_icp(source, target, THRESHOLD, TRANS_INIT), source, target)
    # The same covariances, computed exactly and handed over as the clouds' own.
    source_c = o3d.geometry.PointCloud(source)
    target_c = o3d.geometry.PointCloud(target)
    source_c.covariances = o3d.utility.Matrix3dVector(plane_covariances(source, 1e-3))
    target_c.covariances = o3d.utility.Matrix3dVector(plane_covariances(target, 1e-3))
    show("GicpCovariances", reg.registration_generalized_icp(source_c, target_c, THRESHOLD, TRANS_INIT), source, target)
    show("GicpCauchy", reg.registration_generalized_icp(
        source_c, target_c, THRESHOLD, TRANS_INIT, reg.TransformationEstimationForGeneralizedICP(kernel=reg.CauchyLoss(k=0.5))),
        source, target)
    # Neither covariances nor normals: normals from 20 nearest neighbours, then covariances.
    source_p = o3d.geometry.PointCloud(source.points)
    target_p = o3d.geometry.PointCloud(target.points)
    show("GicpPoints", reg.registration_generalized_icp(source_p, target_p, THRESHOLD, TRANS_INIT), source, target)

    show("Symmetric", reg.registration_symmetric_icp(source, target, THRESHOLD, TRANS_INIT), source, target)
    show("SymmetricGm", reg.registration_symmetric_icp(
        source, target, THRESHOLD, TRANS_INIT, reg.TransformationEstimationSymmetric(kernel=reg.GMLoss(k=0.01))),
        source, target)

    show("PlaneTukey", reg.registration_icp(
        source, target, THRESHOLD, TRANS_INIT, reg.TransformationEstimationPointToPlane(reg.TukeyLoss(k=0.01))),
        source, target)
    show("PlaneL1", reg.registration_icp(
        source, target, THRESHOLD, TRANS_INIT, reg.TransformationEstimationPointToPlane(reg.L1Loss())),
        source, target)

    residuals = [0.0, 0.2, -0.3, 0.5, 0.7]
    print(f"// kernel weights at r = {residuals} (tests/core/robust_kernel_test.cpp)")
    for kernel in (reg.HuberLoss(k=0.5), reg.CauchyLoss(k=0.5), reg.GMLoss(k=0.5), reg.TukeyLoss(k=0.5)):
        print(f"{type(kernel).__name__}(0.5): {[kernel.weight(r) for r in residuals]!r}")

    n = np.asarray(source.normals)
    print(f"// source normals within 8.1 deg of -x (where Open3D's covariance keeps diag(eps, 1, 1)): "
          f"{int((n[:, 0] < -0.99).sum())}")


if __name__ == "__main__":
    main()
