#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers for bindings/python/tests/test_{boundingbox,hull,lineset,voxelgrid,octree,covariances}.py,
from Open3D 0.20.

Usage: /tmp/o3dref/bin/python tools/reference/record_python_round2.py
The inputs are synthesized here (seeded numpy) exactly as the tests synthesize them (see make_inputs, copied
into the tests' helpers); each printed line is a value a test compares against.
Fingerprints: fp(a) = sum_i (i + 1) * a_i over the flattened array (so order and values must match).
"""
import numpy as np
import open3d as o3d

V3 = o3d.utility.Vector3dVector


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def show(name, value):
    print(f"{name} = {value!r}")


def rot_xyz(a, b, c):
    return o3d.geometry.get_rotation_matrix_from_xyz((a, b, c))


def make_inputs():
    rng = np.random.default_rng(7)
    cloud = rng.uniform(-1.0, 1.0, size=(200, 3)) * np.array([3.0, 2.0, 1.0])
    colors = rng.uniform(0.0, 1.0, size=(200, 3))
    return cloud, colors


cloud, colors = make_inputs()
pcd = o3d.geometry.PointCloud(V3(cloud))
pcd.colors = V3(colors)

# ---- oriented boxes
obb = pcd.get_oriented_bounding_box()
show("obb.volume", obb.volume())
show("obb.extent_sorted", sorted(np.asarray(obb.extent).tolist()))
show("obb.center", np.asarray(obb.center).tolist())
inside = obb.get_point_indices_within_bounding_box(V3(cloud))
show("obb.n_inside", len(inside))
robust = pcd.get_oriented_bounding_box(robust=True)
show("obb_robust.volume", robust.volume())
aabb = o3d.geometry.AxisAlignedBoundingBox((-1, -2, -3), (1, 2, 3))
show("aabb.box_points", np.asarray(aabb.get_box_points()).tolist())
show("aabb_obb.box_points", np.asarray(o3d.geometry.OrientedBoundingBox.create_from_axis_aligned_bounding_box(aabb).get_box_points()).tolist())
box = o3d.geometry.OrientedBoundingBox((1.0, 2.0, 3.0), rot_xyz(0.3, -0.2, 0.5), (2.0, 1.0, 0.5))
show("obb_given.box_points", np.asarray(box.get_box_points()).tolist())
show("obb_given.min_bound", np.asarray(box.get_min_bound()).tolist())
show("obb_given.max_bound", np.asarray(box.get_max_bound()).tolist())
box2 = o3d.geometry.OrientedBoundingBox((0.0, 0.0, 0.0), rot_xyz(0.0, 0.0, 0.6), (3.0, 1.0, 1.0))
idx = box2.get_point_indices_within_bounding_box(V3(cloud))
show("obb_rotz.indices", sorted(idx))
show("crop_obb.n", len(pcd.crop(box2).points))
show("crop_obb_fp", fp(pcd.crop(box2).points))
mesh = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=10)
show("sphere_obb.volume", mesh.get_oriented_bounding_box().volume())
show("sphere_crop.counts", (lambda m: (len(m.vertices), len(m.triangles)))(mesh.crop(box2)))

# ---- convex hull and hidden-point removal
hull, hidx = pcd.compute_convex_hull()
show("hull.counts", (len(hull.vertices), len(hull.triangles)))
show("hull.indices_sorted", sorted(hidx))
show("hull.volume", hull.get_volume())
show("hull.area", hull.get_surface_area())
mhull, mhidx = mesh.compute_convex_hull()
show("sphere_hull.counts", (len(mhull.vertices), len(mhull.triangles)))
sphere_pts = np.asarray(mesh.vertices)
spcd = o3d.geometry.PointCloud(V3(sphere_pts))
_, vis = spcd.hidden_point_removal((0.0, 0.0, 5.0), 500.0)
show("hpr.n_visible", len(vis))
show("hpr.visible_fp", fp(sorted(vis)))

# ---- covariances
pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamKNN(knn=10))
show("cov_knn10.fp", fp(np.asarray(pcd.covariances)))
show("cov_knn10[0]", np.asarray(pcd.covariances)[0].tolist())
pcd.estimate_covariances()
show("cov_default.fp", fp(np.asarray(pcd.covariances)))
pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamRadius(radius=0.5))
show("cov_r05.fp", fp(np.asarray(pcd.covariances)))

# ---- line sets
ls = o3d.geometry.LineSet.create_from_triangle_mesh(o3d.geometry.TriangleMesh.create_box())
show("box_edges.n", len(ls.lines))
show("box_edges.sorted", sorted(tuple(sorted(map(int, l))) for l in np.asarray(ls.lines)))
ls = o3d.geometry.LineSet.create_from_oriented_bounding_box(box)
show("obb_lines.lines", np.asarray(ls.lines).tolist())
show("obb_lines.points_fp", fp(ls.points))
ls = o3d.geometry.LineSet.create_from_axis_aligned_bounding_box(aabb)
show("aabb_lines.lines", np.asarray(ls.lines).tolist())
show("aabb_lines.points", np.asarray(ls.points).tolist())

# ---- voxel grids
vg = o3d.geometry.VoxelGrid.create_from_point_cloud(pcd, 0.5)
vox = sorted(vg.get_voxels(), key=lambda v: tuple(v.grid_index))
show("vg.n", len(vox))
show("vg.origin", np.asarray(vg.origin).tolist())
show("vg.index_fp", fp([v.grid_index for v in vox]))
show("vg.color_fp", fp([v.color for v in vox]))
show("vg.get_voxel", np.asarray(vg.get_voxel((0.1, 0.2, 0.3))).tolist())
queries = np.array([[0.0, 0.0, 0.0], [2.9, 1.9, 0.9], [10.0, 0.0, 0.0], [-2.0, 1.5, -0.5]])
show("vg.included", vg.check_if_included(V3(queries)))
vgb = o3d.geometry.VoxelGrid.create_from_point_cloud_within_bounds(pcd, 0.5, (-1.0, -1.0, -1.0), (1.0, 1.0, 1.0))
voxb = sorted(vgb.get_voxels(), key=lambda v: tuple(v.grid_index))
show("vgb.n", len(voxb))
show("vgb.index_fp", fp([v.grid_index for v in voxb]))
show("vgb.color_fp", fp([v.color for v in voxb]))
# o3d ignores points outside the bounds (header contract); Open3D keeps them, so compare on the points inside.
keep = np.all((cloud >= -1.0) & (cloud <= 1.0), axis=1)
pin = o3d.geometry.PointCloud(V3(cloud[keep]))
pin.colors = V3(colors[keep])
vgi = o3d.geometry.VoxelGrid.create_from_point_cloud_within_bounds(pin, 0.5, (-1.0, -1.0, -1.0), (1.0, 1.0, 1.0))
voxi = sorted(vgi.get_voxels(), key=lambda v: tuple(v.grid_index))
show("vgi.n", len(voxi))
show("vgi.index_fp", fp([v.grid_index for v in voxi]))
show("vgi.color_fp", fp([v.color for v in voxi]))
vgm = o3d.geometry.VoxelGrid.create_from_triangle_mesh(o3d.geometry.TriangleMesh.create_box(), 0.3)
voxm = sorted(vgm.get_voxels(), key=lambda v: tuple(v.grid_index))
show("vgm.n", len(voxm))
show("vgm.origin", np.asarray(vgm.origin).tolist())
show("vgm.index_fp", fp([v.grid_index for v in voxm]))

# ---- octree
oc = o3d.geometry.Octree(3)
oc.convert_from_point_cloud(pcd, size_expand=0.01)
show("oc.origin", np.asarray(oc.origin).tolist())
show("oc.size", oc.size)
for q in ([0.1, 0.2, 0.3], cloud[5].tolist(), [2.5, -1.5, 0.8]):
    leaf, info = oc.locate_leaf_node(np.array(q))
    if leaf is None:
        show(f"oc.leaf{q}", None)
    else:
        show(f"oc.leaf{q}", (sorted(leaf.indices), np.asarray(leaf.color).tolist(), np.asarray(info.origin).tolist(),
                             info.size, info.depth, info.child_index))

# ---- the compat script (bindings/python/tests/compat_scripts/round2_tutorial.py): its `result`, last line
import pathlib  # noqa: E402

script = pathlib.Path(__file__).resolve().parents[2] / "bindings/python/tests/compat_scripts/round2_tutorial.py"
ns = {"open3d": o3d, "np": np, "result": {}}
exec(compile(script.read_text(), str(script), "exec"), ns)
show("round2_tutorial", ns["result"])
