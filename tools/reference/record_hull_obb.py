#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D 0.20's convex hull, oriented box, hidden-point removal and covariance numbers on
cloud_bin_0, for tests/core/{convex_hull,oriented_bounding_box,point_cloud_covariances}_test.cpp.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_hull_obb.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import os
import sys

import numpy as np
import open3d as o3d

# Fixed, spread-out indices into cloud_bin_0 (the covariance test repeats them).
COV_INDICES = [0, 500, 1000, 2000, 3902]
HPR_CAMERA = [0.0, 0.0, 5.0]
HPR_RADIUS = 500.0


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def vec(v):
    return "{" + ", ".join(f"{x:.12g}" for x in np.asarray(v).ravel()) + "}"


def main():
    pcd = o3d.io.read_point_cloud(os.path.join(data_root(), "open3d", "Feature", "cloud_bin_0.pcd"))
    print("points", len(pcd.points))

    hull, idx = pcd.compute_convex_hull()
    print("hull vertices", len(hull.vertices), "triangles", len(hull.triangles))
    print(f"hull area {hull.get_surface_area():.12g} volume {hull.get_volume():.12g}")
    print("hull index set checksum (sum of indices)", int(np.asarray(idx).sum()))

    hull_j, idx_j = pcd.compute_convex_hull(joggle_inputs=True)
    print(f"joggled hull vertices {len(hull_j.vertices)} area {hull_j.get_surface_area():.12g}")

    obb = pcd.get_oriented_bounding_box()
    print(f"obb volume {obb.volume():.12g}")
    print("obb center", vec(obb.center))
    print("obb extent", vec(obb.extent))
    print("obb R", vec(obb.R))
    inside = obb.get_point_indices_within_bounding_box(pcd.points)
    print("obb points inside", len(inside))

    mesh_hpr, idx_hpr = pcd.hidden_point_removal(HPR_CAMERA, HPR_RADIUS)
    print("hpr camera", HPR_CAMERA, "radius", HPR_RADIUS, "visible", len(idx_hpr),
          "triangles", len(mesh_hpr.triangles))

    for name, param in [("knn30", o3d.geometry.KDTreeSearchParamKNN(30)),
                        ("hybrid0.05_20", o3d.geometry.KDTreeSearchParamHybrid(0.05, 20)),
                        ("radius0.02", o3d.geometry.KDTreeSearchParamRadius(0.02))]:
        c = o3d.geometry.PointCloud(pcd)
        c.estimate_covariances(param)
        cov = np.asarray(c.covariances)
        identity = int(sum(np.allclose(m, np.eye(3)) for m in cov))
        print(name, "identity count", identity)
        for i in COV_INDICES:
            print(f"  cov[{i}] =", vec(cov[i]))


if __name__ == "__main__":
    main()
