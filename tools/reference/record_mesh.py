#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers for tests/core/{triangle_mesh,mesh_cleanup,mesh_topology}_test.cpp, from Open3D 0.20.

Usage: /tmp/o3dref/bin/python tools/reference/record_mesh.py [DATA_ROOT]
(DATA_ROOT defaults to /work/shared/data.) Each printed line is a number a test compares against.
Fingerprints: fp(a) = sum_i (i + 1) * a_i over the flattened array (so order and values must match).
"""
import sys

import numpy as np
import open3d as o3d

DATA = sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data"


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def show(name, value):
    print(f"{name} = {value!r}")


def knot():
    return o3d.io.read_triangle_mesh(f"{DATA}/open3d/knot.ply")


m = knot()
show("knot.counts", (len(m.vertices), len(m.triangles)))
show("knot.area", m.get_surface_area())
show("knot.euler", m.euler_poincare_characteristic())
show("knot.edge_manifold", (m.is_edge_manifold(True), m.is_edge_manifold(False)))
show("knot.vertex_manifold", m.is_vertex_manifold())
show("knot.self_intersecting", m.is_self_intersecting())
show("knot.watertight", m.is_watertight())
show("knot.orientable", m.is_orientable())
show("knot.center", list(m.get_center()))
show("knot.min_bound", list(m.get_min_bound()))
show("knot.max_bound", list(m.get_max_bound()))
if m.is_watertight():
    show("knot.volume", m.get_volume())
c, n, a = m.cluster_connected_triangles()
show("knot.clusters", (len(n), list(n)[:5], list(np.asarray(a))[:5]))

m.compute_vertex_normals()
show("knot.fp_vertex_normals", fp(m.vertex_normals))
show("knot.fp_triangle_normals", fp(m.triangle_normals))
m2 = knot()
m2.compute_vertex_normals(normalized=False)
show("knot.fp_vertex_normals_raw", fp(m2.vertex_normals))

d = knot().remove_duplicated_vertices()
show("knot.dedup.counts", (len(d.vertices), len(d.triangles)))
show("knot.dedup.fp_triangles", fp(d.triangles))
show("knot.dedup.euler", d.euler_poincare_characteristic())
show("knot.dedup.watertight", d.is_watertight())
show("knot.dedup.orientable", d.is_orientable())
show("knot.dedup.self_intersecting", d.is_self_intersecting())
if d.is_watertight() and d.is_orientable():
    show("knot.dedup.volume", d.get_volume())

for eps in (4.0, 9.0):
    mc = knot().merge_close_vertices(eps)
    show(f"knot.merge{eps}.counts", (len(mc.vertices), len(mc.triangles)))
    show(f"knot.merge{eps}.fp_vertices", fp(mc.vertices))
    show(f"knot.merge{eps}.fp_triangles", fp(mc.triangles))

t = knot().remove_duplicated_vertices().remove_degenerate_triangles().remove_unreferenced_vertices()
show("knot.cleaned.counts", (len(t.vertices), len(t.triangles)))

# A unit cube with shared corners, as the tests build it.
V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
T = [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
     [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
cube = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(T))
show("cube.area_volume_euler", (cube.get_surface_area(), cube.get_volume(), cube.euler_poincare_characteristic()))
show("cube.flags", (cube.is_watertight(), cube.is_orientable(), cube.is_self_intersecting()))
cube.compute_vertex_normals()
show("cube.vertex_normal0", list(np.asarray(cube.vertex_normals)[0]))

# The cube with a fin on edge (0, 1): small fin, then a fin larger than the cube's triangles.
for name, y in (("fin_small", -0.1), ("fin_big", -5.0)):
    f = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V + [[0.5, y, 0.0]]),
                                  o3d.utility.Vector3iVector(T + [[0, 1, 8]]))
    show(f"{name}.flags", (f.is_edge_manifold(True), f.is_orientable()))
    f.remove_non_manifold_edges()
    show(f"{name}.after", np.asarray(f.triangles).tolist())

# A Moebius strip of 24 quads, as mesh_topology_test.cpp builds it.
n = 24
MV, MT = [], []
for i in range(n):
    u = 2 * np.pi * i / n
    for s in (-0.3, 0.3):
        r = 1 + s * np.cos(u / 2)
        MV.append([r * np.cos(u), r * np.sin(u), s * np.sin(u / 2)])
for i in range(n):
    a, b = 2 * i, 2 * i + 1
    c, d = (2 * (i + 1), 2 * (i + 1) + 1) if i + 1 < n else (1, 0)
    MT += [[a, c, d], [a, d, b]]
mob = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(MV), o3d.utility.Vector3iVector(MT))
show("moebius", (mob.is_edge_manifold(True), mob.is_orientable(), mob.euler_poincare_characteristic()))
