#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D 0.20's numbers for tests/core/{voxel_grid_edit,voxel_grid_carving,octree_edit}_test.cpp:
dense grids, mesh voxelization within bounds, depth-map and silhouette carving, octree insertion,
traversal and the octree <-> voxel grid conversions, all on small synthetic inputs built the same way in
the tests (float32 images from the same formulas, rotation entries printed with repr).

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_voxel_edit_octree.py

Checksum of a voxel set sorted by grid index (as o3d stores it):
    sum over rank r (0-based) of (r + 1) * (i + 1009 * j + 1009^2 * k)
"""
import numpy as np
import open3d as o3d


def sorted_indices(grid):
    idx = np.array([v.grid_index for v in grid.get_voxels()], dtype=np.int64).reshape(-1, 3)
    order = np.lexsort((idx[:, 2], idx[:, 1], idx[:, 0]))
    return idx[order]


def checksum(idx):
    keys = idx[:, 0] + 1009 * idx[:, 1] + 1009 * 1009 * idx[:, 2]
    return int(np.sum((np.arange(len(idx)) + 1) * keys))


def dense():
    print("== dense")
    g = o3d.geometry.VoxelGrid.create_dense([1, 2, 3], [0.1, 0.2, 0.3], 0.3, 1.0, 0.95, 0.44)
    print("count", len(g.get_voxels()), "max index", sorted_indices(g).max(0))
    for w in (0.75, 0.749, 0.14, 0.16):
        print("width", w, "->", len(o3d.geometry.VoxelGrid.create_dense([0, 0, 0], [0, 0, 0], 0.3, w, 0.3, 0.3).get_voxels()))
    g = o3d.geometry.VoxelGrid.create_dense([0, 0, 0], [0, 0, 0], 0.5, 1, 1, 1)
    print("bounding points of (1, 0, 1):", np.asarray(g.get_voxel_bounding_points([1, 0, 1])).tolist())


def mesh_within_bounds():
    print("== mesh within bounds")
    # An irregular closed tetrahedron plus a sliver, inside [-0.2, -0.1, 0.05] .. [1.3, 1.2, 1.1].
    v = np.array([[0.13, 0.07, 0.21], [1.07, 0.29, 0.33], [0.41, 1.03, 0.17], [0.52, 0.46, 0.97],
                  [0.9, 0.9, 0.6], [0.95, 0.85, 0.62]], dtype=float)
    t = np.array([[0, 1, 2], [0, 1, 3], [1, 2, 3], [0, 2, 3], [3, 4, 5]], dtype=np.int32)
    m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(v), o3d.utility.Vector3iVector(t))
    lo, hi = np.array([-0.2, -0.1, 0.05]), np.array([1.3, 1.2, 1.1])
    g = o3d.geometry.VoxelGrid.create_from_triangle_mesh_within_bounds(m, 0.1, lo, hi)
    idx = sorted_indices(g)
    print("inside: count", len(idx), "checksum", checksum(idx), "min", idx.min(0), "max", idx.max(0))
    # Tighter bounds cutting the mesh: Open3D 0.20 keeps every touched cell; the cells in
    # [0, floor((hi - lo) / s)] are what o3d keeps.
    lo2, hi2 = np.array([0.3, 0.25, 0.2]), np.array([0.8, 0.7, 0.65])
    g = o3d.geometry.VoxelGrid.create_from_triangle_mesh_within_bounds(m, 0.1, lo2, hi2)
    idx = sorted_indices(g)
    last = np.floor((hi2 - lo2) / 0.1)
    keep = np.all((idx >= 0) & (idx <= last), axis=1)
    print("cut: Open3D count", len(idx), "in range", int(keep.sum()), "checksum", checksum(idx[keep]), "last", last)
    # A wavy 36 x 36 grid of quads (2592 triangles) in the unit cube, voxel 0.02.
    n = 36
    v = [(i / n, j / n, 0.5 + 0.2 * np.sin(6.0 * i / n) * np.cos(5.0 * j / n)) for j in range(n + 1) for i in range(n + 1)]
    t = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            t += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(np.array(v)),
                                  o3d.utility.Vector3iVector(np.array(t, dtype=np.int32)))
    g = o3d.geometry.VoxelGrid.create_from_triangle_mesh_within_bounds(m, 0.02, [0, 0, 0], [1, 1, 1])
    idx = sorted_indices(g)
    print("wavy: count", len(idx), "checksum", checksum(idx), "min", idx.min(0), "max", idx.max(0))


W, H, FX, FY, CX, CY = 40, 30, 30.0, 31.0, 19.5, 14.25
RY = np.array([[0.8, 0.0, -0.6], [0.0, 1.0, 0.0], [0.6, 0.0, 0.8]])
RX = np.array([[1.0, 0.0, 0.0], [0.0, 0.96, -0.28], [0.0, 0.28, 0.96]])


def camera(rotated):
    p = o3d.camera.PinholeCameraParameters()
    p.intrinsic = o3d.camera.PinholeCameraIntrinsic(W, H, FX, FY, CX, CY)
    e = np.eye(4)
    if rotated:
        e[:3, :3] = RX @ RY
    e[:3, 3] = [0.05, -0.03, 3.0]
    p.extrinsic = e
    return p


def cube():
    return o3d.geometry.VoxelGrid.create_dense([-0.5, -0.5, -0.5], [0.2, 0.3, 0.4], 0.1, 1, 1, 1)


def carving():
    print("== carving")
    print("rotation RX @ RY =", [repr(float(x)) for x in (RX @ RY).ravel()])
    u, v = np.meshgrid(np.arange(W), np.arange(H))
    ramp = (2.6 + 0.02 * u + 0.015 * v).astype(np.float32)   # float64 formula, then float32
    ramp[5:9, 10:14] = 0.0                                     # a hole with no measurement
    disc = (((u - 19.5) ** 2 + (v - 14.25) ** 2) <= 3.0 ** 2).astype(np.float32)
    for rotated in (False, True):
        for keep in (False, True):
            g = cube()
            g.carve_depth_map(o3d.geometry.Image(ramp), camera(rotated), keep_voxels_outside_image=keep)
            idx = sorted_indices(g)
            print("depth ramp rotated", rotated, "keep", keep, "count", len(idx), "checksum", checksum(idx))
            g = cube()
            g.carve_silhouette(o3d.geometry.Image(disc), camera(rotated), keep_voxels_outside_image=keep)
            idx = sorted_indices(g)
            print("disc rotated", rotated, "keep", keep, "count", len(idx), "checksum", checksum(idx))
    # A wide camera close to the cube: part of it leaves the image.
    p = camera(True)
    e = np.array(p.extrinsic)
    e[:3, 3] = [0.4, 0.1, 1.4]
    p.extrinsic = e
    for keep in (False, True):
        g = cube()
        g.carve_silhouette(o3d.geometry.Image(disc), p, keep_voxels_outside_image=keep)
        idx = sorted_indices(g)
        print("near disc keep", keep, "count", len(idx), "checksum", checksum(idx))
    g = cube()
    g.carve_depth_map(o3d.geometry.Image(np.full((H, W), 3.05, np.float32)), camera(False))
    print("constant depth 3.05:", len(g.get_voxels()))


def octree():
    print("== octree")
    print("is_point_in_bound", o3d.geometry.Octree.is_point_in_bound([1, 0, 0], [0, 0, 0], 1.0),
          o3d.geometry.Octree.is_point_in_bound([0, 0, 0], [0, 0, 0], 1.0))
    t = o3d.geometry.Octree(2, [0, 0, 0], 4.0)
    pts = [[0.5, 0.5, 0.5], [3.5, 0.5, 0.5], [0.6, 0.6, 0.6], [1.5, 2.5, 3.5], [5, 5, 5]]
    for i, p in enumerate(pts):
        t.insert_point(p, o3d.geometry.OctreePointColorLeafNode.get_init_function(),
                       o3d.geometry.OctreePointColorLeafNode.get_update_function(i, [i / 10, 0, 0]),
                       o3d.geometry.OctreeInternalPointNode.get_init_function(),
                       o3d.geometry.OctreeInternalPointNode.get_update_function(i))
    order = []

    def visit(node, info):
        leaf = isinstance(node, o3d.geometry.OctreeLeafNode)
        order.append((info.depth, info.child_index, tuple(info.origin), info.size,
                      list(node.indices) if leaf else None))
        return False
    t.traverse(visit)
    for o in order:
        print("  visit", o)
    stopped = []
    t.traverse(lambda n, i: stopped.append((i.depth, i.child_index)) or (i.depth == 1 and i.child_index == 0))
    print("  skipping the children of (1, 0):", stopped)

    g = o3d.geometry.VoxelGrid()
    g.voxel_size = 0.3
    g.origin = [0.1, -0.2, 0.05]
    for idx in ([0, 0, 0], [4, 1, 2], [2, 2, 2], [1, 3, 0]):
        g.add_voxel(o3d.geometry.Voxel(idx, [idx[0] / 10, 0.5, idx[2] / 4]))
    t = o3d.geometry.Octree(2)
    t.create_from_voxel_grid(g)
    print("from voxel grid: origin", t.origin, "size", t.size, "max_depth", t.max_depth)
    t.traverse(lambda n, i: print("  leaf", i.child_index, i.origin, i.size, n.color)
               if isinstance(n, o3d.geometry.OctreeLeafNode) else False)
    vg = t.to_voxel_grid()
    print("to_voxel_grid (0.20 bug): voxel_size", vg.voxel_size, "indices", sorted_indices(vg).tolist())


if __name__ == "__main__":
    print("open3d", o3d.__version__)
    dense()
    mesh_within_bounds()
    carving()
    octree()
