#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's global-registration numbers on the cloud_bin pair, for tests/core/ransac_test.cpp and
tests/core/fgr_test.cpp.

The source (cloud_bin_0) is moved by the tests' known motion: 75 degrees about the axis (0.3, -1, 0.5)
through its centroid, then (0.4, -0.2, 0.3). Features are the stored Feature/cloud_bin_*.fpfh.bin.
RANSAC is random (its fitness is printed over several seeds); FGR without the tuple test is deterministic,
so its transformation can be compared to rounding. decrease_mu is always passed explicitly: Open3D's C++
default (and the paper's) is True, but its Python binding defaults to False (Open3D issue #4976).

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_global_registration.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import os
import sys

import numpy as np
import open3d as o3d

reg = o3d.pipelines.registration


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def motion_about_centroid(points):
    axis = np.array([0.3, -1.0, 0.5])
    axis /= np.linalg.norm(axis)
    angle = np.deg2rad(75.0)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    r = np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k
    c = points.mean(axis=0)
    m = np.eye(4)
    m[:3, :3] = r
    m[:3, 3] = c - r @ c + np.array([0.4, -0.2, 0.3])
    return m


def angle_deg(a, b):
    d = a[:3, :3].T @ b[:3, :3]
    return np.rad2deg(np.arccos(np.clip((np.trace(d) - 1) / 2, -1, 1)))


def show(name, result):
    t = np.asarray(result.transformation)
    print(f"// {name}")
    print(f"{name}_fitness = {result.fitness!r}")
    print(f"{name}_inlier_rmse = {result.inlier_rmse!r}")
    print(f"{name}_correspondences = {len(result.correspondence_set)}")
    print(f"{name}_transformation = {{{', '.join(repr(float(v)) for v in t.ravel())}}}")


def main():
    feature = os.path.join(data_root(), "open3d", "Feature")
    source = o3d.io.read_point_cloud(os.path.join(feature, "cloud_bin_0.pcd"))
    target = o3d.io.read_point_cloud(os.path.join(feature, "cloud_bin_1.pcd"))
    fs = o3d.io.read_feature(os.path.join(feature, "cloud_bin_0.fpfh.bin"))
    ft = o3d.io.read_feature(os.path.join(feature, "cloud_bin_1.fpfh.bin"))
    motion = motion_about_centroid(np.asarray(source.points))
    moved = o3d.geometry.PointCloud(source)
    moved.transform(motion)
    print(f"// Open3D {o3d.__version__}, numpy {np.__version__}; source {len(source.points)} points moved by the "
          f"tests' 75 deg motion, target {len(target.points)} points, stored FPFH features")

    checkers = [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(0.075)]
    for mutual in (False, True):
        for n in (3, 4):
            fits = []
            worst = 0.0
            for seed in range(5):
                o3d.utility.random.seed(seed)
                r = reg.registration_ransac_based_on_feature_matching(
                    moved, target, fs, ft, mutual, 0.075, reg.TransformationEstimationPointToPoint(False), n,
                    checkers, reg.RANSACConvergenceCriteria(100000, 0.999))
                fits.append(r.fitness)
                worst = max(worst, angle_deg(np.asarray(r.transformation), np.linalg.inv(motion)))
            print(f"// ransac mutual={mutual} ransac_n={n}: fitness over seeds 0-4 {min(fits):.4f}..{max(fits):.4f}, "
                  f"worst angle to motion^-1 {worst:.2f} deg")

    for decrease_mu in (True, False):
        for absolute in (False, True):
            option = reg.FastGlobalRegistrationOption(maximum_correspondence_distance=0.025, tuple_test=False,
                                                      decrease_mu=decrease_mu, use_absolute_scale=absolute)
            name = f"fgr_no_tuple{'_gnc' if decrease_mu else '_fixed_mu'}{'_absolute' if absolute else ''}"
            show(name, reg.registration_fgr_based_on_feature_matching(moved, target, fs, ft, option))
    fits = []
    worst = 0.0
    for seed in range(5):
        o3d.utility.random.seed(seed)
        r = reg.registration_fgr_based_on_feature_matching(
            moved, target, fs, ft,
            reg.FastGlobalRegistrationOption(maximum_correspondence_distance=0.025, decrease_mu=True))
        fits.append(r.fitness)
        worst = max(worst, angle_deg(np.asarray(r.transformation), np.linalg.inv(motion)))
    print(f"// fgr with tuple test and decrease_mu: fitness over seeds 0-4 {min(fits):.4f}..{max(fits):.4f}, "
          f"worst angle to motion^-1 {worst:.2f} deg")

if __name__ == "__main__":
    main()
