#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D 0.20's ball-pivoting triangle counts on the deterministic inputs of
tests/core/ball_pivoting_test.cpp (the test builds the same clouds with the same splitmix64 stream).

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_ball_pivoting.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import math
import os
import sys

import numpy as np
import open3d as o3d

MASK = (1 << 64) - 1


class SplitMix64:
    """Same generator as the test's: uniform doubles in [0, 1) from the top 53 bits."""

    def __init__(self, seed):
        self.state = seed & MASK

    def uniform(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        z ^= z >> 31
        return (z >> 11) * (1.0 / 9007199254740992.0)


def sphere(n, radius, seed):
    rng = SplitMix64(seed)
    pts, nrm = [], []
    for _ in range(n):
        z = 2.0 * rng.uniform() - 1.0
        phi = 2.0 * math.pi * rng.uniform()
        s = math.sqrt(max(0.0, 1.0 - z * z))
        d = (s * math.cos(phi), s * math.sin(phi), z)
        nrm.append(d)
        pts.append(tuple(radius * c for c in d))
    return pts, nrm


def torus(n, major, minor, seed):
    """Area-uniform: the tube angle is accepted with probability (R + r cos t) / (R + r)."""
    rng = SplitMix64(seed)
    pts, nrm = [], []
    while len(pts) < n:
        t = 2.0 * math.pi * rng.uniform()
        p = 2.0 * math.pi * rng.uniform()
        if rng.uniform() * (major + minor) > major + minor * math.cos(t):
            continue
        ring = major + minor * math.cos(t)
        pts.append((ring * math.cos(p), ring * math.sin(p), minor * math.sin(t)))
        nrm.append((math.cos(t) * math.cos(p), math.cos(t) * math.sin(p), math.sin(t)))
    return pts, nrm


def cloud(pts, nrm):
    pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.array(pts)))
    pc.normals = o3d.utility.Vector3dVector(np.array(nrm))
    return pc


def report(name, pc, radii):
    mesh = o3d.geometry.TriangleMesh.create_from_point_cloud_ball_pivoting(pc, o3d.utility.DoubleVector(radii))
    used = len(np.unique(np.asarray(mesh.triangles))) if len(mesh.triangles) else 0
    print(f"{name}: radii {[round(r, 6) for r in radii]} -> {len(mesh.triangles)} triangles, {used} vertices used, "
          f"area {mesh.get_surface_area():.6f}, edge manifold {mesh.is_edge_manifold(False)} (closed)")


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def main():
    print("open3d", o3d.__version__)
    n = 3000
    r = 1.5 * math.sqrt(4.0 * math.pi / n)
    pc = cloud(*sphere(n, 1.0, 1))
    report("sphere 3000 seed 1", pc, [r])
    report("sphere 3000 seed 1", pc, [r, 2 * r])

    n = 4000
    r = 1.5 * math.sqrt(4.0 * math.pi ** 2 * 1.0 * 0.4 / n)
    report("torus 1/0.4 4000 seed 2", cloud(*torus(n, 1.0, 0.4, 2)), [r, 2 * r])

    # knot.ply's own vertices, with the area-weighted vertex normals of its triangles.
    knot = o3d.io.read_triangle_mesh(os.path.join(data_root(), "open3d", "knot.ply"))
    knot.compute_vertex_normals()
    pc = cloud(np.asarray(knot.vertices), np.asarray(knot.vertex_normals))
    spacing = float(np.mean(pc.compute_nearest_neighbor_distance()))
    print(f"knot vertices: {len(pc.points)}, mean spacing {spacing:.6f}")
    report("knot vertices", pc, [5.0, 10.0])


if __name__ == "__main__":
    main()
