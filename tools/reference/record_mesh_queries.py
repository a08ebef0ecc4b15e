#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference answers for tests/core/mesh_queries_test.cpp, from Open3D 0.20: non-manifold edges and vertices,
self-intersecting triangle pairs, mesh-mesh intersection, orient_triangles, filter_sharpen and the bounded
primitives (create_ellipsoid, create_from_oriented_bounding_box / _ellipsoid).

Usage: /tmp/o3dref/bin/python tools/reference/record_mesh_queries.py
Each printed line is a value a test compares against. Open3D returns the non-manifold edges in hash order:
they are printed sorted, as o3d returns them.
"""
import numpy as np
import open3d as o3d

G = o3d.geometry
V3 = o3d.utility.Vector3dVector
V3i = o3d.utility.Vector3iVector


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def show(name, value):
    print(f"{name} = {value!r}")


def mesh(v, t):
    return G.TriangleMesh(V3(np.asarray(v, dtype=np.float64)), V3i(np.asarray(t, dtype=np.int32)))


def edges(m, allow):
    return sorted(tuple(int(x) for x in e) for e in np.asarray(m.get_non_manifold_edges(allow)))


# Three triangles on the edge (0, 1).
fan = mesh([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0], [0.5, 0, 1]], [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
show("fan.edges", (edges(fan, True), edges(fan, False)))
show("fan.vertices", sorted(fan.get_non_manifold_vertices()))

# An open strip of 4 triangles over a 3 x 2 grid.
strip = mesh([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]],
             [[0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4]])
show("strip.edges", (edges(strip, True), edges(strip, False)))
show("strip.vertices", sorted(strip.get_non_manifold_vertices()))

# Two tetrahedra sharing vertex 0 (a bow tie).
TV = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]]
TT = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 5, 4], [0, 4, 6], [0, 6, 5], [4, 5, 6]]
bow = mesh(TV, TT)
show("bowtie", (sorted(bow.get_non_manifold_vertices()), edges(bow, True), edges(bow, False), bow.is_vertex_manifold()))

# Two crossing triangles, then a triangle touching nothing.
cross = mesh([[0, 0, 0], [2, 0, 0], [0, 2, 0], [0.5, 0.5, -1], [0.5, 0.5, 1], [1.5, -0.5, 0.2],
              [5, 5, 5], [6, 5, 5], [5, 6, 5]], [[0, 1, 2], [3, 4, 5], [6, 7, 8]])
show("cross.pairs", np.asarray(cross.get_self_intersecting_triangles()).tolist())

# A unit box and a rotated, shifted box, merged into one mesh.
b1 = G.TriangleMesh.create_box()
b2 = G.TriangleMesh.create_box(0.8, 0.9, 1.1)
b2.rotate(G.get_rotation_matrix_from_xyz([0.3, 0.2, 0.1]), center=[0, 0, 0])
b2.translate([0.37, 0.21, 0.43])
boxes = mesh(np.vstack([np.asarray(b1.vertices), np.asarray(b2.vertices)]),
             np.vstack([np.asarray(b1.triangles), np.asarray(b2.triangles) + 8]))
show("boxes.b2_vertices", np.asarray(b2.vertices).tolist())
show("boxes.pairs", np.asarray(boxes.get_self_intersecting_triangles()).tolist())
show("boxes.meshes_intersect", b1.is_intersecting(b2))

# Spheres: overlapping, apart, one inside the other (surfaces apart).
s = G.TriangleMesh.create_sphere(1.0, 10)
for name, radius, shift in (("overlap", 1.0, 1.5), ("apart", 1.0, 2.5), ("inside", 0.3, 0.1)):
    o = G.TriangleMesh.create_sphere(radius, 10)
    o.translate([shift, 0, 0])
    show(f"spheres.{name}", (s.is_intersecting(o), o.is_intersecting(s)))

# Orientation: the box with triangles 1, 4, 7 and 10 flipped.
box = G.TriangleMesh.create_box(1.0, 2.0, 3.0)
bt = np.asarray(box.triangles).copy()
for t in (1, 4, 7, 10):
    bt[t] = bt[t][[0, 2, 1]]
flipped = mesh(np.asarray(box.vertices), bt)
show("orient.box.before", (flipped.is_orientable(), flipped.is_watertight()))
ok = flipped.orient_triangles()
show("orient.box.after", (ok, np.asarray(flipped.triangles).tolist(), flipped.get_volume()))

n = 24
MV, MT = [], []
for i in range(n):
    u = 2 * np.pi * i / n
    for s_ in (-0.3, 0.3):
        r = 1 + s_ * np.cos(u / 2)
        MV.append([r * np.cos(u), r * np.sin(u), s_ * np.sin(u / 2)])
for i in range(n):
    a, b = 2 * i, 2 * i + 1
    c, d = (2 * (i + 1), 2 * (i + 1) + 1) if i + 1 < n else (1, 0)
    MT += [[a, c, d], [a, d, b]]
mob = mesh(MV, MT)
show("orient.moebius", mob.orient_triangles())

# Sharpening on two triangles, with normals and colors.
sm = mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5]], [[0, 1, 2], [1, 3, 2]])
sm.vertex_colors = V3(np.array([[0.1, 0.2, 0.3], [0.9, 0.5, 0.5], [0.5, 0.5, 0.5], [0.2, 0.2, 0.9]]))
sm.vertex_normals = V3(np.array([[0, 0, 1], [0, 0.1, 1], [0.1, 0, 1], [0, 0, 1]], dtype=np.float64))
for iters, strength in ((1, 1.0), (2, 0.5)):
    out = sm.filter_sharpen(iters, strength, G.FilterScope.All)
    show(f"sharpen.{iters}.{strength}", (np.asarray(out.vertices).tolist(), np.asarray(out.vertex_normals).tolist(),
                                         np.asarray(out.vertex_colors).tolist()))
sp = G.TriangleMesh.create_sphere(1.0, 6)
out = sp.filter_sharpen(3, 0.1)
show("sharpen.sphere6", (fp(out.vertices), np.asarray(out.vertices)[5].tolist()))

# Ellipsoids.
e = G.TriangleMesh.create_ellipsoid(1.0, 2.0, 3.0, 3, True)
show("ellipsoid.1_2_3_res3", (np.asarray(e.vertices).tolist(), np.asarray(e.triangles).tolist()))
show("ellipsoid.1_2_3_res3.uvs", (len(e.triangle_uvs), fp(e.triangle_uvs), np.asarray(e.triangle_uvs)[:12].tolist(),
                                  np.asarray(e.triangle_uvs)[-6:].tolist()))
e = G.TriangleMesh.create_ellipsoid(0.5, 1.5, 0.7, 20, True)
show("ellipsoid.default_res", (len(e.vertices), len(e.triangles), fp(e.vertices), fp(e.triangles), fp(e.triangle_uvs)))
show("ellipsoid.sphere_equal", [np.array_equal(np.asarray(G.TriangleMesh.create_ellipsoid(r, r, r, k).vertices),
                                               np.asarray(G.TriangleMesh.create_sphere(r, k).vertices))
                                for r, k in ((1.0, 20), (2.5, 7))])

# Meshes of an oriented box and an oriented ellipsoid.
R = G.get_rotation_matrix_from_xyz([0.3, -0.2, 0.7])
ob = G.OrientedBoundingBox(np.array([1.0, -2.0, 0.5]), R, np.array([2.0, 1.0, 0.5]))
bm = G.TriangleMesh.create_from_oriented_bounding_box(ob, np.array([1.0, 1.5, 2.0]), True)
show("obb_mesh", (np.asarray(bm.vertices).tolist(), np.asarray(bm.triangles).tolist()))
show("obb_mesh.uvs", (len(bm.triangle_uvs), fp(bm.triangle_uvs)))
show("obb_mesh.box_points", np.asarray(ob.get_box_points()).tolist())
el = G.OrientedBoundingEllipsoid(np.array([1.0, 2.0, 3.0]), R, np.array([0.5, 1.0, 2.0]))
em = G.TriangleMesh.create_from_oriented_bounding_ellipsoid(el, np.array([2.0, 1.0, 0.5]), 4, False)
show("obe_mesh", (len(em.vertices), len(em.triangles), np.asarray(em.vertices).tolist(),
                  em.has_vertex_colors(), np.asarray(em.vertex_colors)[0].tolist(), em.has_triangle_uvs()))
