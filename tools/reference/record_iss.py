#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Record Open3D's ISS keypoints (o3d.geometry.keypoint.compute_iss_keypoints) for tests/core/iss_keypoints_test.cpp.

Run with the open3d 0.20.0 wheel:  python tools/reference/record_iss.py [data_root]
Prints, per case, the keypoint count and the indices of the first / last keypoints in the input cloud.
"""
import sys

import numpy as np
import open3d as o3d

root = sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data"
o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
print("open3d", o3d.__version__)


def indices_of(cloud, keypoints):
    tree = o3d.geometry.KDTreeFlann(cloud)
    return [tree.search_knn_vector_3d(p, 1)[1][0] for p in np.asarray(keypoints.points)]


def box_grid(step=0.05):
    # Surface of the unit cube on a regular grid (the same points the C++ test builds).
    g = np.round(np.arange(0.0, 1.0 + 1e-9, step), 12)
    pts = set()
    for a in g:
        for b in g:
            for c in (0.0, 1.0):
                pts.add((a, b, c)); pts.add((a, c, b)); pts.add((c, a, b))
    return np.array(sorted(pts))


cases = []
frag = o3d.io.read_point_cloud(f"{root}/open3d/fragment.pcd")
cases.append(("fragment defaults", frag, {}))
cases.append(("fragment salient 0.02 non_max 0.015 gammas 0.9/0.8 min 8", frag,
              dict(salient_radius=0.02, non_max_radius=0.015, gamma_21=0.9, gamma_32=0.8, min_neighbors=8)))
box = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(box_grid()))
cases.append(("unit cube grid step 0.05", box, {}))
m = 4000
i = np.arange(m)
z = 1 - 2 * (i + 0.5) / m
r = np.sqrt(1 - z * z)
t = np.pi * (3 - 5 ** 0.5) * i
sphere = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.c_[r * np.cos(t), r * np.sin(t), z]))
cases.append(("fibonacci sphere 4000", sphere, {}))
cases.append(("fibonacci sphere 4000 gamma_21 0.9", sphere, dict(gamma_21=0.9)))
for name, cloud, kw in cases:
    kp = o3d.geometry.keypoint.compute_iss_keypoints(cloud, **kw)
    idx = indices_of(cloud, kp)
    print(f"{name}: n = {len(cloud.points)}, keypoints = {len(idx)}, first = {idx[:3]}, last = {idx[-3:]}")
    if name.startswith("unit cube"):
        print("  keypoints:", np.asarray(kp.points).round(3).tolist())
