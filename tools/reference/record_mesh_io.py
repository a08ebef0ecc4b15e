#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers for tests/core/mesh_io_data_files_test.cpp and tests/capi/test_mesh_io.c, from Open3D 0.20.

Usage: /tmp/o3dref/bin/python tools/reference/record_mesh_io.py [data_root]   (default ../shared/data)

For each shared mesh: vertex and triangle counts and the axis-aligned bounding box from
open3d.io.read_triangle_mesh. crate.obj is the exception: Open3D 0.20's read_triangle_mesh reads OBJ through
Assimp, which returns an empty mesh for this file (its faces carry UVs but no normals), so its numbers come from
open3d.io.read_triangle_model, whose mesh splits vertices by UV (24); o3d keeps one vertex per 'v' line (8), which
the test checks against the file itself, and compares the corner positions and UVs of the first triangles.
"""
import os
import sys

import numpy as np
import open3d as o3d

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data")
d = os.path.join(root, "open3d")


def show(name, mesh):
    lo, hi = mesh.get_min_bound(), mesh.get_max_bound()
    print(f"{name}: vertices {len(mesh.vertices)} triangles {len(mesh.triangles)} "
          f"normals {mesh.has_vertex_normals()} colors {mesh.has_vertex_colors()} uvs {len(mesh.triangle_uvs)}")
    print(f"  min {float(lo[0])!r}, {float(lo[1])!r}, {float(lo[2])!r}")
    print(f"  max {float(hi[0])!r}, {float(hi[1])!r}, {float(hi[2])!r}")


for f in ("knot.ply", "sphere.ply", "bathtub_0154.ply", "color.ply", "test_sample_ascii.ply", "test_sample_custom.ply",
          "test_sample_wrong_format.ply"):
    show(f, o3d.io.read_triangle_mesh(os.path.join(d, f)))
    pp = o3d.io.read_triangle_mesh(os.path.join(d, f), enable_post_processing=True)
    print(f"  post-processed: vertices {len(pp.vertices)} triangles {len(pp.triangles)}")

model = o3d.io.read_triangle_model(os.path.join(d, "crate", "crate.obj"))
for m in model.meshes:
    show("crate.obj (read_triangle_model)", m.mesh)
for mat in model.materials:
    if mat.albedo_img is not None:
        a = np.asarray(mat.albedo_img)
        print(f"  texture {a.shape[1]} x {a.shape[0]} x {a.shape[2] if a.ndim == 3 else 1}")

# color.ply carries per-vertex normals and colours: sums over all vertices pin their values and order.
cm = o3d.io.read_triangle_mesh(os.path.join(d, "color.ply"))
n, c = np.asarray(cm.vertex_normals), np.asarray(cm.vertex_colors)
print(f"color.ply normal sums {float(n[:, 0].sum())!r}, {float(n[:, 1].sum())!r}, {float(n[:, 2].sum())!r}")
print(f"color.ply color sums {float(c[:, 0].sum())!r}, {float(c[:, 1].sum())!r}, {float(c[:, 2].sum())!r}")
print(f"color.ply triangle index sums {int(np.asarray(cm.triangles).astype(np.int64).sum())}")

# crate.obj's first quad "f 5/1 6/2 2/3 1/4": the corner positions and UVs of its two triangles, as Open3D splits it.
cm = model.meshes[0].mesh
v, t, uv = np.asarray(cm.vertices), np.asarray(cm.triangles), np.asarray(cm.triangle_uvs)
for k in range(2):
    print(f"crate.obj triangle {k}: positions {v[t[k]].tolist()} uvs {uv[3 * k:3 * k + 3].tolist()}")
