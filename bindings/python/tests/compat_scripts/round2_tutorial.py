# An Open3D-style script over boxes, hulls, line sets, voxel grids, octrees and covariances. It runs with
# `open3d` bound to Open3D or to o3d (test_open3d_compat_round2.py) and fills `result`.
pts = np.random.default_rng(11).uniform(-1.0, 1.0, size=(300, 3)) * [2.0, 1.0, 0.5]
pcd = open3d.geometry.PointCloud()
pcd.points = open3d.utility.Vector3dVector(pts)

obb = pcd.get_oriented_bounding_box()
half = open3d.geometry.OrientedBoundingBox(obb.center, obb.R, obb.extent * 0.5)
result["obb"] = (round(obb.volume(), 6), len(pcd.crop(half).points), len(half.get_point_indices_within_bounding_box(pcd.points)))

hull, idx = pcd.compute_convex_hull()
hull_lines = open3d.geometry.LineSet.create_from_triangle_mesh(hull)
result["hull"] = (len(hull.vertices), len(hull.triangles), len(hull_lines.lines), sorted(idx)[:5], round(hull.get_volume(), 6))

lines = open3d.geometry.LineSet.create_from_oriented_bounding_box(obb)
lines.paint_uniform_color([1.0, 0.0, 0.0])
result["lines"] = (len(lines.points), len(lines.lines), np.asarray(lines.colors)[0].tolist())

grid = open3d.geometry.VoxelGrid.create_from_point_cloud(pcd, voxel_size=0.25)
result["voxels"] = (len(grid.get_voxels()), sum(grid.check_if_included(open3d.utility.Vector3dVector(pts))))

octree = open3d.geometry.Octree(max_depth=4)
octree.convert_from_point_cloud(pcd, size_expand=0.01)
leaf, info = octree.locate_leaf_node(pts[0])
result["octree"] = (round(octree.size, 6), info.depth, 0 in leaf.indices)

pcd.estimate_covariances(open3d.geometry.KDTreeSearchParamKNN(knn=20))
covs = np.asarray(pcd.covariances)
result["covariances"] = (covs.shape, round(float(np.trace(covs.sum(axis=0))), 6))

_, visible = pcd.hidden_point_removal([0.0, 0.0, 3.0], 100.0)
result["hpr"] = len(visible)
