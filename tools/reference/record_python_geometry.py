#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers for bindings/python/tests/test_{trianglemesh,image,rgbd,camera}*.py, from Open3D 0.20.

Usage: /tmp/o3dref/bin/python tools/reference/record_python_geometry.py [DATA_ROOT]
(DATA_ROOT defaults to /work/shared/data.) The same calls run unchanged with `import o3d as o3d` in the
tests; each line printed here is a number a test compares against.

Fingerprints: fp(a) = sum_i (i + 1) * a_i over the flattened array (so order and values must match).
"""
import sys

import numpy as np
import open3d as o3d

DATA = sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data"
G = o3d.geometry.TriangleMesh


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def show(name, value):
    print(f"{name} = {value!r}")


def mesh_summary(name, m):
    show(f"{name}.counts", (len(m.vertices), len(m.triangles)))
    show(f"{name}.area", m.get_surface_area())
    show(f"{name}.fp_vertices", fp(m.vertices))
    show(f"{name}.fp_triangles", fp(m.triangles))


# ---- primitives and queries
box = G.create_box()
mesh_summary("box", box)
show("box.volume", box.get_volume())
show("box.euler", box.euler_poincare_characteristic())
box.compute_vertex_normals()
show("box.fp_vertex_normals", fp(box.vertex_normals))
show("box.fp_triangle_normals", fp(box.triangle_normals))
for name, make in [("sphere", lambda: G.create_sphere()), ("tetrahedron", lambda: G.create_tetrahedron()),
                   ("octahedron", lambda: G.create_octahedron()), ("icosahedron", lambda: G.create_icosahedron()),
                   ("torus", lambda: G.create_torus()), ("cylinder", lambda: G.create_cylinder()),
                   ("cone", lambda: G.create_cone()), ("arrow", lambda: G.create_arrow()),
                   ("frame", lambda: G.create_coordinate_frame())]:
    mesh_summary(name, make())
show("torus.euler", G.create_torus().euler_poincare_characteristic())

# ---- processing on deterministic inputs
tet = G.create_tetrahedron()
mesh_summary("tet_midpoint1", tet.subdivide_midpoint(number_of_iterations=1))
mesh_summary("oct_loop1", G.create_octahedron().subdivide_loop(number_of_iterations=1))
base = G.create_octahedron().subdivide_midpoint(2)
mesh_summary("oct_smooth_simple2", base.filter_smooth_simple(number_of_iterations=2))
mesh_summary("oct_smooth_laplacian3", base.filter_smooth_laplacian(number_of_iterations=3, lambda_filter=0.5))
mesh_summary("oct_smooth_taubin5", base.filter_smooth_taubin(number_of_iterations=5))
vc = G.create_sphere().simplify_vertex_clustering(voxel_size=0.5)
show("sphere_vc05.counts", (len(vc.vertices), len(vc.triangles)))
show("sphere_vc05.area", vc.get_surface_area())

two = G.create_box() + G.create_box().translate((3, 0, 0))
c, n, a = two.cluster_connected_triangles()
show("two_boxes.clusters", list(np.asarray(c)))
show("two_boxes.n", list(n))
show("two_boxes.area", list(np.asarray(a)))

cropped = G.create_box().subdivide_midpoint(2).crop(
    o3d.geometry.AxisAlignedBoundingBox((-1, -1, -1), (1, 1, 0.5)))
mesh_summary("box_sub2_crop", cropped)

# ---- files
knot = o3d.io.read_triangle_mesh(f"{DATA}/open3d/knot.ply")
mesh_summary("knot", knot)
show("knot.watertight", knot.is_watertight())
show("knot.euler", knot.euler_poincare_characteristic())
crate = o3d.io.read_triangle_mesh(f"{DATA}/open3d/crate/crate.obj")
show("crate.counts", (len(crate.vertices), len(crate.triangles)))
show("crate.area", crate.get_surface_area())
show("crate.uvs", (crate.has_triangle_uvs(), len(crate.triangle_uvs), len(crate.textures)))

# ---- images
f = (np.sin(np.arange(30, dtype=np.float32)).reshape(5, 6) + 1.0).astype(np.float32)
img = o3d.geometry.Image(f)
for t in ["Gaussian3", "Gaussian5", "Gaussian7", "Sobel3dx", "Sobel3dy"]:
    show(f"img.filter.{t}", fp(img.filter(getattr(o3d.geometry.ImageFilterType, t))))
big = o3d.geometry.Image((np.cos(np.arange(64 * 48, dtype=np.float32) * 0.1).reshape(48, 64)).astype(np.float32))
for g in (True, False):
    pyr = big.create_pyramid(3, g)
    show(f"pyramid.{g}.shapes", [np.asarray(p).shape for p in pyr])
    show(f"pyramid.{g}.fp", [fp(p) for p in pyr])

# ---- RGB-D
color = o3d.io.read_image(f"{DATA}/open3d/RGBD/color/00000.jpg")
depth = o3d.io.read_image(f"{DATA}/open3d/RGBD/depth/00000.png")
show("depth00000.fp", fp(depth))
rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth)
show("rgbd00000.depth_sum", float(np.asarray(rgbd.depth, dtype=np.float64).sum()))
show("rgbd00000.color_mean", float(np.asarray(rgbd.color, dtype=np.float64).mean()))
K = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
pcd = o3d.geometry.PointCloud.create_from_rgbd_image(rgbd, K)
show("rgbd00000.cloud_n", len(pcd.points))
show("rgbd00000.cloud_center", list(pcd.get_center()))
show("rgbd00000.cloud_color_mean", list(np.asarray(pcd.colors).mean(axis=0)))
pd = o3d.geometry.PointCloud.create_from_depth_image(depth, K, depth_trunc=3.0, stride=2)
show("depth00000.stride2.n", len(pd.points))
show("depth00000.stride2.center", list(pd.get_center()))
tum = o3d.geometry.RGBDImage.create_from_tum_format(
    o3d.io.read_image(f"{DATA}/open3d/RGBD/other_formats/TUM_color.png"),
    o3d.io.read_image(f"{DATA}/open3d/RGBD/other_formats/TUM_depth.png"))
show("tum.depth_sum", float(np.asarray(tum.depth, dtype=np.float64).sum()))
lr = o3d.geometry.RGBDImage.create_from_color_and_depth(
    o3d.io.read_image(f"{DATA}/livingroom1_clean_micro/image/00000.jpg"),
    o3d.io.read_image(f"{DATA}/livingroom1_clean_micro/depth/00000.png"), convert_rgb_to_intensity=False)
lp = o3d.geometry.PointCloud.create_from_rgbd_image(lr, K)
show("livingroom00000.cloud_n", len(lp.points))
show("livingroom00000.cloud_center", list(lp.get_center()))

# ---- camera
k = o3d.io.read_pinhole_camera_intrinsic(f"{DATA}/open3d/camera_primesense.json")
show("camera_primesense", (k.width, k.height, k.get_focal_length(), k.get_principal_point()))
traj = o3d.io.read_pinhole_camera_trajectory(f"{DATA}/open3d/camera_trajectory.json")
show("camera_trajectory.n", len(traj.parameters))
show("camera_trajectory.fp0", fp(traj.parameters[0].extrinsic))
log = o3d.io.read_pinhole_camera_trajectory(f"{DATA}/open3d/RGBD/trajectory.log")
show("trajectory_log.n", len(log.parameters))
show("trajectory_log.fp0", fp(log.parameters[0].extrinsic))

# ---- the shared Open3D-style script (bindings/python/tests/compat_scripts/geometry_tutorial.py)
import pathlib  # noqa: E402

script = pathlib.Path(__file__).resolve().parents[2] / "bindings/python/tests/compat_scripts/geometry_tutorial.py"
ns = {"open3d": o3d, "np": np, "result": {}}
exec(script.read_text(), ns)
show("geometry_tutorial.result", ns["result"])
