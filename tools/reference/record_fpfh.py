#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's FPFH numbers on the stored cloud_bin scans, for tests/core/fpfh_reference_test.cpp,
tests/core/feature_io_test.cpp and tests/core/fpfh_matching_test.cpp.

The input is Feature/cloud_bin_*.pcd as stored (points and normals read from the file, no downsampling),
so both libraries see bit-identical doubles.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_fpfh.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import os
import sys

import numpy as np
import open3d as o3d

reg = o3d.pipelines.registration
geo = o3d.geometry

COLUMNS = [0, 1, 1234, 3902]  # descriptors printed in full (cloud_bin_0 has 3903 points)
MATCH_RADIUS = 0.075  # a match is right when the matched point lies within this of the query point


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def values(v):
    return "{" + ", ".join(repr(float(x)) for x in v) + "}"


def show(name, feature, columns):
    data = np.asarray(feature.data)
    print(f"// {name}: {data.shape[0]} x {data.shape[1]}, {int((np.abs(data).sum(0) > 0).sum())} non-zero columns")
    print(f"{name}_bin_totals = {values(data.sum(1))}")
    for c in columns:
        print(f"{name}_column_{c} = {values(data[:, c])}")


def matching_score(target_points, target_features, query_points, query_features):
    """Share of query points whose nearest target descriptor (L2) belongs to a point within MATCH_RADIUS."""
    feature = reg.Feature()
    feature.data = target_features
    tree = geo.KDTreeFlann(feature)
    right = 0
    for i in range(query_features.shape[1]):
        _, idx, _ = tree.search_knn_vector_xd(query_features[:, i], 1)
        right += np.linalg.norm(target_points[idx[0]] - query_points[i]) <= MATCH_RADIUS
    return right / query_features.shape[1]


def own_spfh(cloud, param):
    """SPFH of every point, as Open3D's ComputeSPFHFeature (numpy; Open3D does not expose it)."""
    points, normals = np.asarray(cloud.points), np.asarray(cloud.normals)
    tree = geo.KDTreeFlann(cloud)
    spfh = np.zeros((33, len(points)))
    for i in range(len(points)):
        k, idx, _ = tree.search_vector_3d(points[i], param)
        if k < 2:
            continue
        idx = np.asarray(idx)[1:]
        dp = points[idx] - points[i]
        d = np.linalg.norm(dp, axis=1)
        n1 = np.broadcast_to(normals[i], dp.shape)
        n2 = normals[idx]
        a1, a2 = (n1 * dp).sum(1) / d, (n2 * dp).sum(1) / d
        swap = (np.arccos(np.abs(a1)) > np.arccos(np.abs(a2)))[:, None]
        u, t, dp = np.where(swap, n2, n1), np.where(swap, n1, n2), np.where(swap, -dp, dp)
        cos_n = np.where(swap[:, 0], -a2, a1)
        v = np.cross(dp, u)
        v /= np.linalg.norm(v, axis=1)[:, None]
        w = np.cross(u, v)
        angle = np.arctan2((w * t).sum(1), (u * t).sum(1))
        for offset, position in [(0, 11 * (angle + np.pi) / (2 * np.pi)), (11, 11 * ((v * t).sum(1) + 1) * 0.5),
                                 (22, 11 * (cos_n + 1) * 0.5)]:
            np.add.at(spfh[:, i], np.clip(np.floor(position), 0, 10).astype(int) + offset, 100.0 / (k - 1))
    return spfh


def main():
    folder = os.path.join(data_root(), "open3d", "Feature")
    cloud0 = o3d.io.read_point_cloud(os.path.join(folder, "cloud_bin_0.pcd"))
    cloud1 = o3d.io.read_point_cloud(os.path.join(folder, "cloud_bin_1.pcd"))
    stored0 = o3d.io.read_feature(os.path.join(folder, "cloud_bin_0.fpfh.bin"))
    stored1 = o3d.io.read_feature(os.path.join(folder, "cloud_bin_1.fpfh.bin"))
    print(f"// Open3D {o3d.__version__}, numpy {np.__version__}; cloud_bin_0 {len(cloud0.points)} points, "
          f"cloud_bin_1 {len(cloud1.points)} points")

    hybrid = geo.KDTreeSearchParamHybrid(radius=0.25, max_nn=100)
    show("hybrid_bin0", reg.compute_fpfh_feature(cloud0, hybrid), COLUMNS)
    show("radius_bin0", reg.compute_fpfh_feature(cloud0, geo.KDTreeSearchParamRadius(0.25)), [1234])
    show("knn_bin1", reg.compute_fpfh_feature(cloud1, geo.KDTreeSearchParamKNN(30)), [7])

    # indices: duplicates count once, columns come in ascending point order
    subset = reg.compute_fpfh_feature(cloud0, hybrid, [3902, 5, 5, 17])
    full = np.asarray(reg.compute_fpfh_feature(cloud0, hybrid).data)
    sub = np.asarray(subset.data)
    print(f"// indices [3902, 5, 5, 17] -> {sub.shape}; max |subset - full[:, [5, 17, 3902]]| = "
          f"{float(np.abs(sub - full[:, [5, 17, 3902]]).max())!r}")

    s0, s1 = np.asarray(stored0.data), np.asarray(stored1.data)
    print(f"// stored features: {s0.shape}, {s1.shape}")
    print(f"stored0_column_0 = {values(s0[:, 0])}")
    print(f"stored1_column_3457 = {values(s1[:, 3457])}")
    print(f"stored0_total = {float(s0.sum())!r}; stored1_total = {float(s1.sum())!r}")

    # Which parameters made the stored files? Their sub-histograms sum to 100, so they predate Open3D's
    # adding each point's own SPFH (0.20's sum to 200): compare them with 0.20's FPFH minus that SPFH.
    print("// stored cloud_bin_0 vs Open3D 0.20 FPFH minus own SPFH: median and max |difference|")
    for name, param in [("hybrid 0.25/100", hybrid), ("radius 0.25", geo.KDTreeSearchParamRadius(0.25)),
                        ("hybrid 0.25/200", geo.KDTreeSearchParamHybrid(radius=0.25, max_nn=200)),
                        ("radius 0.2", geo.KDTreeSearchParamRadius(0.2)), ("knn 100", geo.KDTreeSearchParamKNN(100))]:
        older = np.asarray(reg.compute_fpfh_feature(cloud0, param).data) - own_spfh(cloud0, param)
        diff = np.abs(older - s0)
        print(f"// {name}: median {float(np.median(diff)):.3g}, max {float(diff.max()):.3g}")

    p0, p1 = np.asarray(cloud0.points), np.asarray(cloud1.points)
    print(f"// matching score (cloud_bin_1 queries against cloud_bin_0, right within {MATCH_RADIUS} m)")
    print(f"stored = {float(matching_score(p0, s0, p1, s1))!r}")
    for name, param in [("hybrid 0.25/100", hybrid), ("radius 0.25", geo.KDTreeSearchParamRadius(0.25))]:
        f0 = np.asarray(reg.compute_fpfh_feature(cloud0, param).data)
        f1 = np.asarray(reg.compute_fpfh_feature(cloud1, param).data)
        print(f"open3d {name} = {float(matching_score(p0, f0, p1, f1))!r}")


if __name__ == "__main__":
    main()
