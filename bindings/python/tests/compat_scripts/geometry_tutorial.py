# An Open3D-style script using only Open3D 0.20's API. test_open3d_compat_geometry.py runs it with o3d bound
# to the name `open3d`; tools/reference/record_python_geometry.py runs it with the real Open3D and prints
# `result`, recorded in the test. Inputs: `open3d`, `np`, `result` (a dict to fill).
mesh = open3d.geometry.TriangleMesh.create_box(width=2.0, height=1.0, depth=0.5)
mesh.compute_vertex_normals()
result["box"] = (len(mesh.vertices), len(mesh.triangles), round(mesh.get_surface_area(), 9),
                 round(mesh.get_volume(), 9), mesh.is_watertight())
fine = mesh.subdivide_midpoint(number_of_iterations=2)
smooth = fine.filter_smooth_laplacian(number_of_iterations=2)
result["smooth"] = (len(smooth.vertices), len(smooth.triangles), round(smooth.get_surface_area(), 9))
smooth.paint_uniform_color([1, 0.706, 0])
torus = open3d.geometry.TriangleMesh.create_torus()
combined = smooth + torus.translate((5, 0, 0))
clusters, n_triangles, areas = combined.cluster_connected_triangles()
result["clusters"] = ([int(n) for n in n_triangles], [round(float(a), 9) for a in np.asarray(areas)])
depth = open3d.geometry.Image(np.full((48, 64), 1500, dtype=np.uint16))
color = open3d.geometry.Image(np.full((48, 64, 3), 200, dtype=np.uint8))
rgbd = open3d.geometry.RGBDImage.create_from_color_and_depth(color, depth, convert_rgb_to_intensity=False)
intrinsic = open3d.camera.PinholeCameraIntrinsic(64, 48, 50.0, 50.0, 31.5, 23.5)
pcd = open3d.geometry.PointCloud.create_from_rgbd_image(rgbd, intrinsic)
result["rgbd"] = (len(pcd.points), [round(float(c), 9) for c in pcd.get_center()],
                  [round(float(c), 6) for c in np.asarray(pcd.colors)[0]])
