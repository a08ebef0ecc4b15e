#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers for tests/core/mesh_primitives_test.cpp, from Open3D 0.20's TriangleMesh.create_*.

Usage: /tmp/o3dref/bin/python tools/reference/record_primitives.py

For each call: vertex and triangle counts, the bounding box, the surface area, and two layout fingerprints:
sum_i (i + 1) * vertex_i (3 numbers, so vertex order and positions must match) and sum_t (t + 1) * triangle_t
(so triangle order and corner order, hence orientation, must match).
"""
import numpy as np
import open3d as o3d

G = o3d.geometry.TriangleMesh

CALLS = [
    ("box(1, 1, 1)", lambda: G.create_box()),
    ("box(1, 2, 3)", lambda: G.create_box(1, 2, 3)),
    ("sphere(1, 20)", lambda: G.create_sphere()),
    ("sphere(2, 3)", lambda: G.create_sphere(2, 3)),
    ("cylinder(1, 2, 20, 4)", lambda: G.create_cylinder()),
    ("cylinder(0.5, 3, 7, 2)", lambda: G.create_cylinder(0.5, 3, 7, 2)),
    ("cone(1, 2, 20, 1)", lambda: G.create_cone()),
    ("cone(0.5, 3, 7, 3)", lambda: G.create_cone(0.5, 3, 7, 3)),
    ("torus(1, 0.5, 30, 20)", lambda: G.create_torus()),
    ("torus(2, 0.25, 5, 4)", lambda: G.create_torus(2, 0.25, 5, 4)),
    ("arrow(1, 1.5, 5, 4, 20, 4, 1)", lambda: G.create_arrow()),
    ("arrow(0.5, 1, 2, 1, 6, 2, 2)", lambda: G.create_arrow(0.5, 1, 2, 1, 6, 2, 2)),
    ("coordinate_frame(1, [0, 0, 0])", lambda: G.create_coordinate_frame()),
    ("coordinate_frame(2, [1, 2, 3])", lambda: G.create_coordinate_frame(2.0, [1, 2, 3])),
    ("tetrahedron(1)", lambda: G.create_tetrahedron()),
    ("octahedron(1)", lambda: G.create_octahedron()),
    ("icosahedron(1)", lambda: G.create_icosahedron()),
    ("tetrahedron(2)", lambda: G.create_tetrahedron(2)),
    ("octahedron(2)", lambda: G.create_octahedron(2)),
    ("icosahedron(2)", lambda: G.create_icosahedron(2)),
]

for name, make in CALLS:
    m = make()
    v = np.asarray(m.vertices)
    t = np.asarray(m.triangles).astype(np.int64)
    lo, hi = m.get_min_bound(), m.get_max_bound()
    fv = ((np.arange(len(v)) + 1)[:, None] * v).sum(axis=0)
    ft = ((np.arange(len(t)) + 1)[:, None] * t).sum(axis=0)
    print(f"{name}: vertices {len(v)} triangles {len(t)} area {m.get_surface_area()!r} "
          f"normals {m.has_vertex_normals()} colors {m.has_vertex_colors()}")
    print(f"  min {float(lo[0])!r}, {float(lo[1])!r}, {float(lo[2])!r}  max {float(hi[0])!r}, {float(hi[1])!r}, {float(hi[2])!r}")
    print(f"  vertex fingerprint {float(fv[0])!r}, {float(fv[1])!r}, {float(fv[2])!r}  triangle fingerprint {ft[0]}, {ft[1]}, {ft[2]}")
    if m.has_vertex_normals():
        n = np.asarray(m.vertex_normals)
        fn = ((np.arange(len(n)) + 1)[:, None] * n).sum(axis=0)
        print(f"  normal fingerprint {float(fn[0])!r}, {float(fn[1])!r}, {float(fn[2])!r}")
    if m.has_vertex_colors():
        c = np.asarray(m.vertex_colors)
        print(f"  color sums {float(c.sum(axis=0)[0])!r}, {float(c.sum(axis=0)[1])!r}, {float(c.sum(axis=0)[2])!r}")
