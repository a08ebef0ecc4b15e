#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers for tests/core/mesh_processing_reference_test.cpp, from Open3D 0.20.

Usage: /tmp/o3dref/bin/python tools/reference/record_mesh_processing.py

The meshes are built here by hand exactly as the test builds them (the UV sphere is checked against
create_sphere below), so nothing depends on o3d's primitives:
  sphere(r, res)  Open3D's create_sphere layout;
  bumpy_grid()    5 x 5 vertices on [0,4]^2, z = 0.3 sin(1.7 x) cos(1.3 y) + 0.05 x y, colors (x/4, y/4, 0.5),
                  each cell split along its (i,j)-(i+1,j+1) diagonal;
  octahedron()    the unit octahedron, outward triangles.
Vertex arrays are summarised by two checksums that depend on values and order:
  weighted = sum_i (i + 1) * (x_i + 2 y_i + 3 z_i),  squares = sum_i |v_i|^2.
"""
import math

import numpy as np
import open3d as o3d


def sphere(r, res):
    v = [[0, 0, r], [0, 0, -r]]
    step = math.pi / res
    for i in range(1, res):
        a = step * i
        for j in range(2 * res):
            t = step * j
            v.append([math.sin(a) * math.cos(t) * r, math.sin(a) * math.sin(t) * r, math.cos(a) * r])
    tris = []
    for j in range(2 * res):
        j1 = (j + 1) % (2 * res)
        tris.append([0, 2 + j, 2 + j1])
        b = 2 + 2 * res * (res - 2)
        tris.append([1, b + j1, b + j])
    for i in range(1, res - 1):
        b1 = 2 + 2 * res * (i - 1)
        b2 = b1 + 2 * res
        for j in range(2 * res):
            j1 = (j + 1) % (2 * res)
            tris.append([b2 + j, b1 + j1, b1 + j])
            tris.append([b2 + j, b2 + j1, b1 + j1])
    return make(v, tris)


def bumpy_grid():
    v, c, tris = [], [], []
    for j in range(5):
        for i in range(5):
            x, y = float(i), float(j)
            v.append([x, y, 0.3 * math.sin(1.7 * x) * math.cos(1.3 * y) + 0.05 * x * y])
            c.append([x / 4, y / 4, 0.5])
    for j in range(4):
        for i in range(4):
            a = j * 5 + i
            tris.append([a, a + 1, a + 6])
            tris.append([a, a + 6, a + 5])
    m = make(v, tris)
    m.vertex_colors = o3d.utility.Vector3dVector(np.array(c))
    return m


def octahedron():
    v = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    tris = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    return make(v, tris)


def make(v, tris):
    m = o3d.geometry.TriangleMesh()
    m.vertices = o3d.utility.Vector3dVector(np.array(v, dtype=float))
    m.triangles = o3d.utility.Vector3iVector(np.array(tris, dtype=np.int32))
    return m


def checksums(a):
    a = np.asarray(a)
    w = np.arange(1, len(a) + 1)
    return float(np.sum(w * (a[:, 0] + 2 * a[:, 1] + 3 * a[:, 2]))), float(np.sum(a * a))


def show(name, arr):
    w, s = checksums(arr)
    print(f"{name}: rows {len(np.asarray(arr))} weighted {w!r} squares {s!r}")


ref = o3d.geometry.TriangleMesh.create_sphere(1.0, 20)
mine = sphere(1.0, 20)
assert np.array_equal(np.asarray(ref.triangles), np.asarray(mine.triangles))
assert np.abs(np.asarray(ref.vertices) - np.asarray(mine.vertices)).max() < 1e-15
print(f"sphere(1,20): area {mine.get_surface_area()!r} volume {mine.get_volume()!r}")

print("== quadric decimation of sphere(1,20) (1520 triangles)")
for target in (760, 300, 100):
    d = mine.simplify_quadric_decimation(target)
    print(f"target {target}: triangles {len(d.triangles)} vertices {len(d.vertices)} area {d.get_surface_area()!r} "
          f"watertight {d.is_watertight()} volume {d.get_volume() if d.is_watertight() else float('nan')!r}")

print("== smoothing of bumpy_grid (vertices, then colors)")
g = bumpy_grid()
for name, out in (("simple 3", g.filter_smooth_simple(3)),
                  ("laplacian 3 lambda 0.5", g.filter_smooth_laplacian(3, 0.5)),
                  ("taubin 4 lambda 0.5 mu -0.53", g.filter_smooth_taubin(4, 0.5, -0.53))):
    show(name + " vertices", out.vertices)
    show(name + " colors", out.vertex_colors)
lap = np.asarray(g.filter_smooth_laplacian(1, 0.5).vertices)
print("laplacian 1 vertex 12 (interior)", [float(x) for x in lap[12]], "vertex 0 (corner)", [float(x) for x in lap[0]])

print("== subdivision")
o = octahedron()
l1 = np.asarray(o.subdivide_loop(1).vertices)
print("octahedron loop 1 vertices:")
for p in l1:
    print("  {" + ", ".join(repr(float(x)) for x in p) + "},")
print("octahedron loop 1 triangles[0..7]:", np.asarray(o.subdivide_loop(1).triangles)[:8].tolist())
show("octahedron loop 2 vertices", o.subdivide_loop(2).vertices)
show("bumpy_grid loop 1 vertices", g.subdivide_loop(1).vertices)
show("bumpy_grid loop 1 colors", g.subdivide_loop(1).vertex_colors)
show("bumpy_grid midpoint 2 vertices", g.subdivide_midpoint(2).vertices)

print("== vertex clustering of bumpy_grid, voxel 1.5")
for name, c in (("average", o3d.geometry.SimplificationContraction.Average),
                ("quadric", o3d.geometry.SimplificationContraction.Quadric)):
    s = g.simplify_vertex_clustering(1.5, c)
    show(name + " vertices", s.vertices)
    tris = sorted(tuple(t) for t in np.asarray(s.triangles).tolist())
    print(f"{name} triangles (sorted) {len(tris)}:", tris)

print("== Poisson-disk vs uniform sampling of sphere(1,20), 400 points: mean nearest-neighbour distance")
for label, fn in (("poisson", lambda: mine.sample_points_poisson_disk(400)),
                  ("uniform", lambda: mine.sample_points_uniformly(400))):
    means, mins = [], []
    for seed in range(10):
        o3d.utility.random.seed(seed)
        pc = fn()
        d = np.asarray(pc.compute_nearest_neighbor_distance())
        means.append(d.mean())
        mins.append(d.min())
    print(f"{label}: mean NN {float(np.mean(means))!r} (seed spread {float(np.std(means))!r}) "
          f"mean of min NN {float(np.mean(mins))!r}")

print("== texture colors: unit square, UV = xy, 2 x 2 texture [[red, green], [blue, white]] (rows top-down)")
m = make([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]])
m.triangle_uvs = o3d.utility.Vector2dVector(np.array([[0, 0], [1, 0], [1, 1], [0, 0], [1, 1], [0, 1]], float))
img = np.zeros((2, 2, 3), np.uint8)
img[0, 0], img[0, 1], img[1, 0], img[1, 1] = [255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]
m.textures = [o3d.geometry.Image(img)]
m.triangle_material_ids = o3d.utility.IntVector([0, 0])
pc = m.sample_points_uniformly(2000)
p, c = np.asarray(pc.points), np.asarray(pc.colors)
for right in (0, 1):
    for top in (0, 1):
        sel = ((p[:, 0] >= 0.5) == bool(right)) & ((p[:, 1] >= 0.5) == bool(top))
        print(f"x >= 0.5: {right}, y >= 0.5: {top} ->", np.unique(np.round(c[sel], 3), axis=0).tolist())
