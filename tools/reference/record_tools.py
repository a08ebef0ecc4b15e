#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Record Open3D 0.20 reference numbers for the point-cloud tools (tests/core/point_cloud_tools_test.cpp).

Usage: python record_tools.py [DATA_ROOT]   (DATA_ROOT defaults to ../shared/data beside the checkout)
Needs the `open3d` wheel (0.20). Prints the numbers the C++ test hard-codes.
"""
import os
import sys

import numpy as np
import open3d as o3d

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data")
pcd = o3d.io.read_point_cloud(os.path.join(root, "open3d", "fragment.pcd"))
print("open3d", o3d.__version__, "fragment.pcd points", len(pcd.points))

_, ind = pcd.remove_statistical_outlier(nb_neighbors=20, std_ratio=2.0)
print("remove_statistical_outlier(20, 2.0) kept", len(ind), "first", ind[:5], "last", ind[-3:])
for r in (0.05, 0.02):
    _, ind = pcd.remove_radius_outlier(nb_points=16, radius=r)
    print(f"remove_radius_outlier(16, {r}) kept", len(ind), "first", ind[:5], "last", ind[-3:])

_, ind = pcd.remove_statistical_outlier(nb_neighbors=20, std_ratio=0.5)
print("remove_statistical_outlier(20, 0.5) kept", len(ind))
box = o3d.geometry.AxisAlignedBoundingBox([0.5, 1.0, 0.6], [2.0, 2.0, 1.2])
print("crop([0.5,1,0.6],[2,2,1.2]) kept", len(pcd.crop(box).points), "inverted", len(pcd.crop(box, invert=True).points))

mean, cov = pcd.compute_mean_and_covariance()
print("mean", repr(mean.tolist()))
print("covariance", repr(cov.tolist()))
md = np.asarray(pcd.compute_mahalanobis_distance())
print("mahalanobis first", repr(md[:3].tolist()), "max", repr(float(md.max())), "mean", repr(float(md.mean())))

down = pcd.voxel_down_sample(0.02)
labels = np.asarray(down.cluster_dbscan(eps=0.05, min_points=10))
print("voxel_down_sample(0.02) points", len(down.points))
print("cluster_dbscan(0.05, 10) clusters", labels.max() + 1, "noise", int((labels < 0).sum()))

plane, inl = pcd.segment_plane(distance_threshold=0.01, ransac_n=3, num_iterations=1000)
print("segment_plane(0.01, 3, 1000) plane", plane.tolist(), "inliers", len(inl))
