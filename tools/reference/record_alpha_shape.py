#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Record Open3D's alpha-shape / TetraMesh numbers used by tests/core/alpha_shape_test.cpp and
tests/core/tetra_mesh_test.cpp.

Run with the Open3D wheel (the numbers in the tests came from open3d 0.20.0):
    python tools/reference/record_alpha_shape.py [/path/to/shared/data]
Inputs are deterministic: the 1440 vertices of open3d/knot.ply, and a torus sampled by golden-ratio
sequences (the same formula as torus_points() in the tests).
"""
import math
import sys

import numpy as np
import open3d as o3d


def torus_points(n):
    pts = []
    for i in range(n):
        fu = i * 0.6180339887498949
        fv = i * 0.7548776662466927
        fs = i * 0.5698402909980532
        u = 2.0 * math.pi * (fu - math.floor(fu))
        v = 2.0 * math.pi * (fv - math.floor(fv))
        r = 0.35 * (1.0 + 0.05 * ((fs - math.floor(fs)) - 0.5))
        pts.append(((1.0 + r * math.cos(v)) * math.cos(u), (1.0 + r * math.cos(v)) * math.sin(u), r * math.sin(v)))
    return np.array(pts)


def report(name, points, alphas):
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    tm, pm = o3d.geometry.TetraMesh.create_from_point_cloud(pcd)
    print(f"{name}: {len(points)} points, {len(tm.vertices)} tetra vertices, {len(tm.tetras)} tetras")
    for alpha in alphas:
        m = o3d.geometry.TriangleMesh.create_from_point_cloud_alpha_shape(pcd, alpha, tm, pm)
        print(f"  alpha {alpha:g}: {len(m.vertices)} vertices, {len(m.triangles)} triangles, "
              f"edge-manifold {m.is_edge_manifold()}, watertight {m.is_watertight()}")
    v = np.asarray(tm.vertices)
    values = v[:, 2] + 0.3 * v[:, 0]
    iso = tm.extract_triangle_mesh(o3d.utility.DoubleVector(values), 0.1)
    print(f"  extract z + 0.3 x = 0.1: {len(iso.vertices)} vertices, {len(iso.triangles)} triangles")


def main():
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
    print("open3d", o3d.__version__)
    data = sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data"
    knot = np.asarray(o3d.io.read_triangle_mesh(f"{data}/open3d/knot.ply").vertices)
    report("knot.ply vertices", knot, [10.0, 15.0, 20.0, 1e6])
    report("torus_points(1500)", torus_points(1500), [0.1, 0.2, 0.5])


if __name__ == "__main__":
    main()
