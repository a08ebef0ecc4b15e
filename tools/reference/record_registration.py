#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's registration numbers on the cloud_bin pair, for tests/core/registration_reference_test.cpp.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_registration.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import os
import sys

import numpy as np
import open3d as o3d

reg = o3d.pipelines.registration

# These downsampled clouds are already roughly aligned (to ~0.4 deg / 17 mm), so ICP starts from identity;
# the ICP tutorial's trans_init belongs to an unaligned pair and finds almost no pairs here.
TRANS_INIT = np.identity(4)
THRESHOLD = 0.02


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def show(name, result):
    t = np.asarray(result.transformation)
    print(f"// {name}: fitness, inlier_rmse, correspondences, transformation (row-major)")
    print(f"{name}_fitness = {result.fitness!r}")
    print(f"{name}_inlier_rmse = {result.inlier_rmse!r}")
    print(f"{name}_correspondences = {len(result.correspondence_set)}")
    print(f"{name}_transformation = {{{', '.join(repr(float(v)) for v in t.ravel())}}}")


def main():
    feature = os.path.join(data_root(), "open3d", "Feature")
    source = o3d.io.read_point_cloud(os.path.join(feature, "cloud_bin_0.pcd"))
    target = o3d.io.read_point_cloud(os.path.join(feature, "cloud_bin_1.pcd"))
    print(f"// Open3D {o3d.__version__}, numpy {np.__version__}; source {len(source.points)} points, "
          f"target {len(target.points)} points, threshold {THRESHOLD}, init = identity")
    show("evaluate", reg.evaluate_registration(source, target, THRESHOLD, TRANS_INIT))
    p2p = reg.TransformationEstimationPointToPoint()
    p2l = reg.TransformationEstimationPointToPlane()
    show("p2p_30", reg.registration_icp(source, target, THRESHOLD, TRANS_INIT, p2p))
    show("p2p_2000", reg.registration_icp(source, target, THRESHOLD, TRANS_INIT, p2p,
                                           reg.ICPConvergenceCriteria(max_iteration=2000)))
    show("p2l_30", reg.registration_icp(source, target, THRESHOLD, TRANS_INIT, p2l))
    info = reg.get_information_matrix_from_point_clouds(source, target, THRESHOLD, TRANS_INIT)
    print(f"info = {{{', '.join(repr(float(v)) for v in np.asarray(info).ravel())}}}")


if __name__ == "__main__":
    main()
