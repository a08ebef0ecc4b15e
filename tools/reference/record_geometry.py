#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's geometry numbers on the shared data, for tests/core/geometry_reference_test.cpp.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_geometry.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import os
import sys

import numpy as np
import open3d as o3d

VOXEL_SIZE = 0.05
NORMAL_RADIUS = 0.1
NORMAL_MAX_NN = 30
# Fixed, spread-out indices into cloud_bin_0 (the test repeats them).
NORMAL_INDICES = [0, 500, 1000, 2000, 3902]


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def vec(v):
    return "{" + ", ".join(repr(float(x)) for x in v) + "}"


def main():
    root = data_root()
    print(f"// Open3D {o3d.__version__}")

    fragment = o3d.io.read_point_cloud(os.path.join(root, "open3d", "fragment.pcd"))
    down = fragment.voxel_down_sample(VOXEL_SIZE)
    # Count and centroid do not depend on the (hash-map) order of Open3D's output.
    print(f"// fragment.pcd: {len(fragment.points)} points; voxel_down_sample({VOXEL_SIZE})")
    print(f"voxel_count = {len(down.points)}")
    print(f"voxel_centroid = {vec(np.asarray(down.points).mean(axis=0))}")
    print(f"voxel_normal_mean = {vec(np.asarray(down.normals).mean(axis=0))}")
    print(f"voxel_color_mean = {vec(np.asarray(down.colors).mean(axis=0))}")

    cloud = o3d.io.read_point_cloud(os.path.join(root, "open3d", "Feature", "cloud_bin_0.pcd"))
    cloud.normals = o3d.utility.Vector3dVector()
    cloud.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=NORMAL_RADIUS, max_nn=NORMAL_MAX_NN))
    normals = np.asarray(cloud.normals)
    print(f"// cloud_bin_0.pcd: {len(cloud.points)} points; estimate_normals(hybrid({NORMAL_RADIUS}, {NORMAL_MAX_NN}))"
          " after clearing normals; sign is arbitrary without prior normals")
    for i in NORMAL_INDICES:
        print(f"normal[{i}] = {vec(normals[i])}")


if __name__ == "__main__":
    main()
