#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D 0.20's voxel-grid, octree and line-set numbers on the shared data, for
tests/core/{voxel_grid,octree,line_set}_test.cpp and tests/capi/test_lineset_voxel_octree.c.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_lineset_voxel_octree.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.

Open3D keeps voxels in a hash map; the checksum below sorts them by grid index first, as o3d exports them:
    checksum = sum over rank r (0-based) of (r + 1) * (i + 1009 * j + 1009^2 * k)
"""
import os
import sys

import numpy as np
import open3d as o3d

CLOUD_VOXEL = 0.05
KNOT_VOXEL = 3.0
OCTREE_DEPTH = 4
OCTREE_EXPAND = 0.01
LOCATE_INDEX = 1000  # the test locates the leaf holding cloud_bin_0's point 1000


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def sorted_indices(grid):
    idx = np.array([v.grid_index for v in grid.get_voxels()], dtype=np.int64)
    order = np.lexsort((idx[:, 2], idx[:, 1], idx[:, 0]))
    return idx[order], order


def checksum(idx):
    keys = idx[:, 0] + 1009 * idx[:, 1] + 1009 * 1009 * idx[:, 2]
    return int(np.sum((np.arange(len(idx), dtype=np.int64) + 1) * keys))


def main():
    root = data_root()
    pcd = o3d.io.read_point_cloud(os.path.join(root, "open3d", "Feature", "cloud_bin_0.pcd"))
    print(f"cloud_bin_0: {len(pcd.points)} points, colors={pcd.has_colors()}")

    grid = o3d.geometry.VoxelGrid.create_from_point_cloud(pcd, CLOUD_VOXEL)
    idx, order = sorted_indices(grid)
    voxels = grid.get_voxels()
    first = voxels[order[0]]
    print(f"voxel {CLOUD_VOXEL}: origin {list(grid.origin)} count {len(idx)} checksum {checksum(idx)}")
    print(f"  first voxel {list(first.grid_index)} color {list(first.color)}")
    colors = np.array([v.color for v in voxels])
    print(f"  color sum {list(colors.sum(axis=0))}")

    mesh = o3d.io.read_triangle_mesh(os.path.join(root, "open3d", "knot.ply"))
    mgrid = o3d.geometry.VoxelGrid.create_from_triangle_mesh(mesh, KNOT_VOXEL)
    midx, _ = sorted_indices(mgrid)
    print(f"knot voxel {KNOT_VOXEL}: origin {list(mgrid.origin)} count {len(midx)} checksum {checksum(midx)}")

    octree = o3d.geometry.Octree(OCTREE_DEPTH)
    octree.convert_from_point_cloud(pcd, OCTREE_EXPAND)
    leaves = [0]

    def count(node, info):
        if isinstance(node, o3d.geometry.OctreeLeafNode):
            leaves[0] += 1
        return False

    octree.traverse(count)
    print(f"octree depth {OCTREE_DEPTH}: origin {list(octree.origin)} size {octree.size!r} leaves {leaves[0]}")
    leaf, info = octree.locate_leaf_node(np.asarray(pcd.points)[LOCATE_INDEX])
    ind = list(leaf.indices)
    print(f"  leaf of point {LOCATE_INDEX}: origin {list(info.origin)} size {info.size!r} depth {info.depth} "
          f"child {info.child_index} color {list(leaf.color)}")
    print(f"  {len(ind)} indices, sum {sum(ind)}, first {sorted(ind)[:5]}")
    # Open3D 0.20's leaf color is the last inserted point's color; o3d's header asks for the mean.
    mean = np.asarray(pcd.colors)[ind].mean(axis=0)
    print(f"  mean color of the leaf's points {[repr(float(x)) for x in mean]}")


if __name__ == "__main__":
    main()
