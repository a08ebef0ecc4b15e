# SPDX-License-Identifier: MIT
"""Open3D 0.20 reference numbers for the C#/Java shape tests (bindings/csharp/tests/Test.cs ShapesTests,
bindings/java/src/test/java/org/o3d/ShapesTest.java). Run: /tmp/o3dref/bin/python record_shapes_bindings.py"""
import numpy as np
import open3d as o3d

g = o3d.geometry
box = g.OrientedBoundingBox.create_from_axis_aligned_bounding_box(g.AxisAlignedBoundingBox([0, 0, 0], [1, 2, 3]))
print("box points", np.asarray(box.get_box_points()).tolist())

pc = g.PointCloud(o3d.utility.Vector3dVector([[0, 0, 0], [1, 1, 1], [0.1, 0.1, 0.1], [0.9, 0.9, 0.9], [0.2, 0.1, 0.1]]))
tree = g.Octree(2)
tree.convert_from_point_cloud(pc, 0.01)
print("octree root", tree.origin, tree.size)
for q in [[0.05, 0.05, 0.05], [0.95, 0.95, 0.95], [0.5, 0.5, 0.5]]:
    leaf, info = tree.locate_leaf_node(q)
    print("leaf", q, None if leaf is None else (leaf.indices, info.origin, info.size, info.depth, info.child_index))

mesh = g.TriangleMesh.create_box()
grid = g.VoxelGrid.create_from_triangle_mesh(mesh, 0.5)
print("mesh voxels", len(grid.get_voxels()), grid.origin)
pts = g.PointCloud(o3d.utility.Vector3dVector([[0, 0, 0], [0.05, 0.05, 0.05], [1, 0, 0], [0, 0, 1]]))
grid = g.VoxelGrid.create_from_point_cloud(pts, 0.5)
print("cloud voxels", sorted(tuple(v.grid_index) for v in grid.get_voxels()), grid.origin)
grid = g.VoxelGrid.create_from_point_cloud_within_bounds(pts, 1.0, [0, 0, 0], [2, 2, 2])
print("bounded voxels", sorted(tuple(v.grid_index) for v in grid.get_voxels()), grid.origin)
print("box mesh edges", len(g.LineSet.create_from_triangle_mesh(mesh).lines))
