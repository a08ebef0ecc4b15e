#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Records Open3D's Poisson reconstruction counts/ranges used by tests/core/poisson_reconstruction_test.cpp.

Run with the open3d 0.20.0 wheel:  /tmp/o3dref/bin/python tools/reference/record_poisson.py
The inputs are deterministic lattices (no RNG) so the C++ test rebuilds exactly the same clouds.
"""
import math

import numpy as np
import open3d as o3d


def fibonacci_sphere(n, radius=1.0):
    golden = math.pi * (3.0 - math.sqrt(5.0))
    pts = []
    for i in range(n):
        z = 1.0 - (2.0 * i + 1.0) / n
        r = math.sqrt(max(0.0, 1.0 - z * z))
        phi = golden * i
        pts.append((r * math.cos(phi), r * math.sin(phi), z))
    p = np.array(pts) * radius
    return p, p / radius


def lattice_torus(n, big=1.0, small=0.4):
    # (u, v) on a rank-1 lattice; v warped so the area density is uniform (area element ~ big + small cos v).
    golden = (math.sqrt(5.0) - 1.0) / 2.0
    pts, nrm = [], []
    for i in range(n):
        u = 2.0 * math.pi * (i + 0.5) / n
        t = (i * golden) % 1.0
        # invert the CDF of v: (v + (small/big) sin v) / (2 pi) = t, by Newton steps
        v = 2.0 * math.pi * t
        for _ in range(30):
            f = v + (small / big) * math.sin(v) - 2.0 * math.pi * t
            v -= f / (1.0 + (small / big) * math.cos(v))
        c = np.array([math.cos(u), math.sin(u), 0.0])
        nv = math.cos(v) * c + np.array([0.0, 0.0, math.sin(v)])
        pts.append(big * c + small * nv)
        nrm.append(nv)
    return np.array(pts), np.array(nrm)


def run(name, p, n, depth):
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(p))
    pcd.normals = o3d.utility.Vector3dVector(n)
    mesh, dens = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=depth, n_threads=1)
    dens = np.asarray(dens)
    print(f"{name} depth={depth}: vertices={len(mesh.vertices)} triangles={len(mesh.triangles)} "
          f"density min={dens.min():.3f} median={np.median(dens):.3f} max={dens.max():.3f}")


if __name__ == "__main__":
    print("open3d", o3d.__version__)
    p, n = fibonacci_sphere(20000)
    run("fibonacci sphere n=20000", p, n, 6)
    run("fibonacci sphere n=20000", p, n, 7)
    p, n = lattice_torus(30000)
    run("lattice torus n=30000 R=1 r=0.4", p, n, 7)
    pcd = o3d.io.read_point_cloud("/work/shared/data/open3d/fragment.pcd")
    mesh, dens = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=8, n_threads=1)
    dens = np.asarray(dens)
    print(f"fragment.pcd depth=8: vertices={len(mesh.vertices)} triangles={len(mesh.triangles)} density "
          f"q01={np.quantile(dens, 0.01):.3f} median={np.median(dens):.3f} max={dens.max():.3f}")
