#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print the Open3D 0.20 numbers that the Rust and C++ binding tests of round 2 compare against:
an axis-aligned box's get_box_points() order and line set, the oriented box of an axis-aligned point
set, and the octree leaves of a six-point colored cloud.
Used by bindings/rust/o3d/tests/{boundingbox,octree}.rs and
bindings/cpp/tests/{hull_and_obb,lineset_voxel_octree}_test.cpp.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_bindings_round2.py

Note: Open3D's OctreePointColorLeafNode keeps the color of the last point inserted; o3d's header
promises the mean color, so the tests check the mean, not the color printed here.
"""
import numpy as np
import open3d as o3d


def main():
    obb = o3d.geometry.OrientedBoundingBox(np.array([1.0, 0.5, 0.25]), np.eye(3), np.array([2.0, 1.0, 0.5]))
    print("box points:", np.asarray(obb.get_box_points()).tolist())
    lines = o3d.geometry.LineSet.create_from_oriented_bounding_box(obb)
    print("box lines:", np.asarray(lines.lines).tolist())

    corners = [[x, y, z] for x in (0, 2) for y in (0, 1) for z in (0, 0.5)]
    pts = np.array(corners + [[1, 0.5, 0.25], [0.5, 0.2, 0.1]], float)
    fitted = o3d.geometry.OrientedBoundingBox.create_from_points(o3d.utility.Vector3dVector(pts))
    print("fitted box: center", fitted.center.tolist(), "extent", fitted.extent.tolist(), "volume", fitted.volume())

    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.array(
        [[0, 0, 0], [4, 4, 4], [0.5, 0.5, 0.5], [3.5, 0.5, 1.5], [3.6, 0.6, 1.6], [1, 3, 2]], float)))
    cloud.colors = o3d.utility.Vector3dVector(np.array(
        [[0, 0, 0], [1, 1, 1], [0.2, 0.4, 0.6], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float))
    tree = o3d.geometry.Octree(2)
    tree.convert_from_point_cloud(cloud, 0.01)
    print("octree root: origin", tree.origin.tolist(), "size", tree.size)
    for query in ([0.5, 0.5, 0.5], [3.5, 0.5, 1.5], [10, 10, 10], [2.5, 2.5, 2.5]):
        node, info = tree.locate_leaf_node(np.array(query, float))
        if node is None:
            print("leaf of", query, ": none")
            continue
        print("leaf of", query, ": origin", info.origin.tolist(), "size", info.size, "depth", info.depth,
              "child_index", info.child_index, "indices", node.indices, "color (last point)", node.color.tolist())
    leaves = []
    tree.traverse(lambda node, info: leaves.append(1) if isinstance(node, o3d.geometry.OctreeLeafNode) else None)
    print("leaf count:", len(leaves))


if __name__ == "__main__":
    main()
