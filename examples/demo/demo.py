#!/usr/bin/env python3
"""The paper's Figure 1 task on a synthesized scan, then ICP, global registration, a mesh pass and the reconstruction of
a short RGB-D stretch (reconstruction.py), printing what it does and writing pictures of it (PNG, rendered by o3d without a display).

Written exactly as it would be for Open3D (`import open3d as o3d`); only the import differs, and the pictures use
two o3d extras of OffscreenRenderer (`render_option`, for normals and wireframe, and `render_to_png`).
No data files are needed: the scan is a noisy sampled room corner with a sphere in it.
"""
import os
import sys
import tempfile
import time

import numpy as np

import o3d

import reconstruction  # noqa: E402 (beside this file)


def synthesize_scan(n=200_000, seed=7):
    rng = np.random.default_rng(seed)
    parts = []
    k = n // 4
    # Floor and two walls of a 4 m room corner, and a 0.5 m sphere standing on the floor.
    parts.append(np.c_[rng.uniform(0, 4, k), rng.uniform(0, 4, k), np.zeros(k)])
    parts.append(np.c_[np.zeros(k), rng.uniform(0, 4, k), rng.uniform(0, 2.5, k)])
    parts.append(np.c_[rng.uniform(0, 4, k), np.zeros(k), rng.uniform(0, 2.5, k)])
    d = rng.normal(size=(n - 3 * k, 3))
    parts.append(d / np.linalg.norm(d, axis=1, keepdims=True) * 0.5 + [2.0, 2.0, 0.5])
    xyz = np.vstack(parts) + rng.normal(scale=0.002, size=(n, 3))
    return xyz


def render_png(path, geometries, eye, center, point_show_normal=False, mesh_show_wireframe=False, up=(0, 0, 1)):
    """Draws [(name, geometry, point_size)] seen from `eye` (`up` up) into a 800 x 600 PNG."""
    rendering = o3d.visualization.rendering
    renderer = rendering.OffscreenRenderer(800, 600)
    renderer.render_option.point_show_normal = point_show_normal
    renderer.render_option.mesh_show_wireframe = mesh_show_wireframe
    renderer.render_option.mesh_show_back_face = True
    for name, geometry, point_size in geometries:
        material = rendering.MaterialRecord()
        material.point_size = point_size
        renderer.scene.add_geometry(name, geometry, material)
    renderer.setup_camera(60.0, center, eye, list(up))
    renderer.render_to_png(path)
    return path


def step(message, fn):
    t0 = time.perf_counter()
    result = fn()
    print(f"  {message} ({(time.perf_counter() - t0) * 1e3:.1f} ms)")
    return result


def peanut_surface(rng, n, radius=0.5, offset=0.35):
    """About `n` points on the boundary of the union of two balls (centres at x = -offset and x = +offset)."""
    d = rng.normal(size=(n, 3))
    d = d / np.linalg.norm(d, axis=1, keepdims=True) * radius
    left, right = d[: n // 2] - [offset, 0, 0], d[n // 2:] + [offset, 0, 0]
    left = left[np.linalg.norm(left - [offset, 0, 0], axis=1) > radius]  # drop what lies inside the other ball
    right = right[np.linalg.norm(right + [offset, 0, 0], axis=1) > radius]
    return np.vstack([left, right])


def surface_from_scan(out_dir):
    """A scan becomes a mesh: consistent normals, screened Poisson, and the same samples by ball pivoting beside it."""
    rng = np.random.default_rng(11)
    # One closed shape with a crease: its normals must be oriented before Poisson can fill it.
    peanut = peanut_surface(rng, 80_000) + [0.0, 0.0, 0.5]
    scan = o3d.geometry.PointCloud()
    scan.points = o3d.utility.Vector3dVector(peanut + rng.normal(scale=0.002, size=peanut.shape))
    step(f"estimate_normals of a {len(scan.points):,}-point scan of a peanut",
         lambda: scan.estimate_normals(search_param=o3d.geometry.KDTreeSearchParamKNN(20)))
    step("orient_normals_consistent_tangent_plane(15)", lambda: scan.orient_normals_consistent_tangent_plane(15))
    # (The lowest point's normal is turned down, as in Open3D, which makes both closed shapes face outwards.)
    mesh, densities = step("create_from_point_cloud_poisson(depth=8)",
                           lambda: o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(scan, depth=8))
    print(f"    {len(mesh.vertices):,} vertices, {len(mesh.triangles):,} triangles, watertight {mesh.is_watertight()}")
    densities = np.asarray(densities)
    # An open scan is trimmed where its samples are sparse (mesh.remove_vertices_by_mask(densities < q)); this
    # closed, evenly sampled one needs no trim: its densities vary little.
    print(f"    densities {densities.min():.2f} .. {densities.max():.2f}")
    mesh.compute_vertex_normals()
    mesh.paint_uniform_color([0.55, 0.7, 0.85])
    spacing = float(np.mean(np.asarray(scan.compute_nearest_neighbor_distance())))
    pivoted = step("create_from_point_cloud_ball_pivoting(radii 2x, 4x the spacing)",
                   lambda: o3d.geometry.TriangleMesh.create_from_point_cloud_ball_pivoting(
                       scan, o3d.utility.DoubleVector([2 * spacing, 4 * spacing])))
    print(f"    {len(pivoted.triangles):,} triangles")
    pivoted.compute_vertex_normals()
    pivoted.paint_uniform_color([0.85, 0.7, 0.5])
    beside = np.identity(4)
    beside[0, 3] = 1.9
    pivoted.transform(beside)
    return step("rendered the Poisson surface beside the ball-pivoting one",
                lambda: render_png(os.path.join(out_dir, "surface.png"), [("poisson", mesh, 1), ("pivoted", pivoted, 1)],
                                   eye=[0.95, -3.4, 2.0], center=[0.95, 0, 0.5]))


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 and sys.argv[1] else tempfile.mkdtemp(prefix="o3d-demo-")
    os.makedirs(out_dir, exist_ok=True)
    print(f"o3d {o3d.__version__}: Figure 1 of the Open3D paper on a synthesized scan")

    scan_path = os.path.join(out_dir, "scan.ply")
    pcd = o3d.geometry.PointCloud()
    pcd.points = o3d.utility.Vector3dVector(synthesize_scan())
    step(f"synthesized a scan of {len(pcd.points):,} points and wrote {scan_path}",
         lambda: o3d.io.write_point_cloud(scan_path, pcd))

    pcd = step("read it back", lambda: o3d.io.read_point_cloud(scan_path))
    downpcd = step("voxel_down_sample(voxel_size=0.05)", lambda: pcd.voxel_down_sample(voxel_size=0.05))
    print(f"    {len(pcd.points):,} -> {len(downpcd.points):,} points")
    step("estimate_normals(KDTreeSearchParamHybrid(radius=0.1, max_nn=30))",
         lambda: downpcd.estimate_normals(search_param=o3d.geometry.KDTreeSearchParamHybrid(radius=0.1, max_nn=30)))
    normals = np.asarray(downpcd.normals)
    floor = np.asarray(downpcd.points)[:, 2] < 0.01
    print(f"    floor normals |n.z| mean = {np.abs(normals[floor, 2]).mean():.4f} (1 = exactly vertical)")
    out_path = os.path.join(out_dir, "downsampled_with_normals.pcd")
    step(f"write_point_cloud({out_path})", lambda: o3d.io.write_point_cloud(out_path, downpcd))
    pictures = []
    pictures.append(step("rendered it, colored by height, with its normals",
                         lambda: render_png(os.path.join(out_dir, "figure1_normals.png"), [("scan", downpcd, 3)],
                                            eye=[6.2, 5.0, 3.6], center=[1.7, 1.7, 0.7], point_show_normal=True)))

    # Pairwise ICP: register a moved copy back onto the original.
    angle = np.deg2rad(5.0)
    moved = np.identity(4)
    moved[:3, :3] = [[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]]
    moved[:3, 3] = [0.05, -0.03, 0.02]
    source = o3d.geometry.PointCloud(downpcd)
    source.transform(moved)
    reg = o3d.pipelines.registration
    result = step("registration_icp(point-to-plane, max_correspondence_distance=0.2)",
                  lambda: reg.registration_icp(source, downpcd, 0.2, np.identity(4),
                                               reg.TransformationEstimationPointToPlane()))
    err = np.abs(result.transformation @ moved - np.identity(4)).max()
    print(f"    fitness {result.fitness:.4f}, inlier_rmse {result.inlier_rmse:.5f}, "
          f"max |T_icp * T_moved - I| = {err:.2e}")

    # Global registration: a copy turned by 60 degrees is too far for ICP; FPFH + RANSAC find it, ICP refines.
    angle = np.deg2rad(60.0)
    far = np.identity(4)
    far[:3, :3] = [[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]]
    far[:3, 3] = [0.5, -0.3, 0.2]
    turned = o3d.geometry.PointCloud(downpcd)
    turned.transform(far)
    fpfh_param = o3d.geometry.KDTreeSearchParamHybrid(radius=0.25, max_nn=100)
    turned_fpfh = step("compute_fpfh_feature(radius=0.25, max_nn=100) of the turned copy",
                       lambda: reg.compute_fpfh_feature(turned, fpfh_param))
    target_fpfh = reg.compute_fpfh_feature(downpcd, fpfh_param)
    checkers = [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(0.075)]
    coarse = step("registration_ransac_based_on_feature_matching(mutual_filter=True, 0.075, seed=1)",
                  lambda: reg.registration_ransac_based_on_feature_matching(
                      turned, downpcd, turned_fpfh, target_fpfh, True, 0.075,
                      reg.TransformationEstimationPointToPoint(False), 3, checkers,
                      reg.RANSACConvergenceCriteria(100000, 0.999), seed=1))
    fine = reg.registration_icp(turned, downpcd, 0.05, coarse.transformation,
                                reg.TransformationEstimationPointToPlane())
    err = np.abs(fine.transformation @ far - np.identity(4)).max()
    print(f"    RANSAC fitness {coarse.fitness:.4f}; after ICP max |T * T_turned - I| = {err:.2e}")
    # Open3D's tutorial colors: the source yellow, the target blue.
    source_colored = o3d.geometry.PointCloud(turned)
    source_colored.paint_uniform_color([1, 0.706, 0])
    target_colored = o3d.geometry.PointCloud(downpcd)
    target_colored.paint_uniform_color([0, 0.651, 0.929])
    view = dict(eye=[8.5, 7.5, 6.5], center=[1.2, 2.0, 0.6])
    pictures.append(step("rendered the pair before registration",
                         lambda: render_png(os.path.join(out_dir, "registration_before.png"),
                                            [("source", source_colored, 2), ("target", target_colored, 4)], **view)))
    source_colored.transform(fine.transformation)
    pictures.append(step("and after",
                         lambda: render_png(os.path.join(out_dir, "registration_after.png"),
                                            [("source", source_colored, 2), ("target", target_colored, 4)], **view)))

    # Meshes: a primitive, decimated, checked, sampled, and its convex hull.
    sphere = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=100)
    simple = step(f"simplify_quadric_decimation of a {len(sphere.triangles):,}-triangle sphere to 2,000",
                  lambda: sphere.simplify_quadric_decimation(target_number_of_triangles=2000))
    print(f"    area {simple.get_surface_area():.4f} (4 pi = {4 * np.pi:.4f}), volume {simple.get_volume():.4f} "
          f"(4/3 pi = {4 / 3 * np.pi:.4f}), watertight {simple.is_watertight()}")
    samples = step("sample_points_poisson_disk(1000)", lambda: simple.sample_points_poisson_disk(1000))
    hull, _ = step("compute_convex_hull of the samples", lambda: samples.compute_convex_hull())
    print(f"    hull: {len(hull.vertices)} vertices, {len(hull.triangles)} triangles, volume {hull.get_volume():.4f}")
    mesh_path = os.path.join(out_dir, "sphere_simplified.ply")
    step(f"write_triangle_mesh({mesh_path})", lambda: o3d.io.write_triangle_mesh(mesh_path, simple))
    simple.compute_vertex_normals()
    simple.paint_uniform_color([0.85, 0.55, 0.35])
    hull_lines = o3d.geometry.LineSet.create_from_triangle_mesh(hull)
    beside = np.identity(4)
    beside[0, 3] = 2.4
    hull_lines.transform(beside)
    samples.transform(beside)
    pictures.append(step("rendered the decimated sphere (wireframe) beside the samples and their hull",
                         lambda: render_png(os.path.join(out_dir, "mesh.png"),
                                            [("sphere", simple, 3), ("samples", samples, 4), ("hull", hull_lines, 1)],
                                            eye=[1.2, -5.5, 2.5], center=[1.2, 0, 0], mesh_show_wireframe=True)))
    pictures.append(surface_from_scan(out_dir))
    pictures.append(reconstruction.run(out_dir, step, render_png))
    print("pictures:")
    for path in pictures:
        print(f"  {path}")
    print(f"done: outputs in {out_dir}")


if __name__ == "__main__":
    main()
