#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Run Open3D's own reconstruction system (the tutorial in Open3D's examples/python/reconstruction_system:
initialize_config, make_fragments, optimize_posegraph, register_fragments, refine_registration, integrate_scene)
with the Open3D wheel, and record a JSON summary (stage times, poses, counts) as the reference for o3d's pipeline.

Those scripts are not in the wheel; this file restates their algorithm (our own code, nothing copied), serially
(python_multi_threading is ignored). Where it departs from them, and why:
- TSDF: Open3D 0.20's legacy ScalableTSDFVolume extracts an EMPTY mesh on this data (a known 0.20 bug), so the
  fragments and the scene are integrated with the tensor o3d.t.geometry.VoxelBlockGrid instead (tsdf/weight/color,
  block resolution 16, voxel tsdf_cubic_size/512, sdf_trunc 0.04, depth_scale, depth_max), meshed with weight
  threshold 0 (the legacy rule "every corner has weight != 0"). Its sdf is the z difference (legacy measures along
  the ray), so surfaces match a working legacy volume but vertex counts can differ a little.
- No keyframe loop closures inside a fragment: Open3D adds them only when OpenCV is installed; it is not here.
- Fragment clouds hold points and colours, as Open3D writes them; the extra key "fragment_normals": true also
  writes the mesh's vertex normals (estimate_normals then orients to them, which changes FPFH and RANSAC).
- Extra key "path_output" (default path_dataset): every output goes under it, the dataset folder stays read-only.
- RANSAC is seeded (o3d.utility.random.seed(0)); Open3D's scripts leave it unseeded.

Usage (Open3D is never a dependency of o3d):
    bench/.venv/bin/python tools/reference/record_reconstruction.py --config CONFIG.json \
        [--make] [--register] [--refine] [--integrate] [--summary OUT.json] [--frames N]
"""
import argparse
import glob
import json
import math
import os
import shutil
import time

import numpy as np
import open3d as o3d
import open3d.core as o3c

reg = o3d.pipelines.registration

DEFAULTS = {  # initialize_config.py's defaults for the keys this system reads
    "path_intrinsic": "", "depth_scale": 1000.0, "depth_max": 3.0, "depth_min": 0.3, "voxel_size": 0.05,
    "depth_diff_max": 0.07, "n_frames_per_fragment": 100, "n_keyframes_per_n_frame": 5,
    "preference_loop_closure_odometry": 0.1, "preference_loop_closure_registration": 5.0, "tsdf_cubic_size": 3.0,
    "icp_method": "color", "global_registration": "ransac", "python_multi_threading": True,
    "folder_fragment": "fragments/", "folder_scene": "scene/",
    "template_fragment_posegraph": "fragments/fragment_%03d.json",
    "template_fragment_posegraph_optimized": "fragments/fragment_optimized_%03d.json",
    "template_fragment_pointcloud": "fragments/fragment_%03d.ply",
    "template_global_posegraph": "scene/global_registration.json",
    "template_global_posegraph_optimized": "scene/global_registration_optimized.json",
    "template_refined_posegraph": "scene/refined_registration.json",
    "template_refined_posegraph_optimized": "scene/refined_registration_optimized.json",
    "template_global_mesh": "scene/integrated.ply", "template_global_traj": "scene/trajectory.log",
    "fragment_normals": False,
}


def load_config(path):
    with open(path) as f:
        config = json.load(f)
    for key, value in DEFAULTS.items():
        config.setdefault(key, value)
    config.setdefault("path_output", config["path_dataset"])
    if config["icp_method"] != "color" or config["global_registration"] != "ransac":
        raise SystemExit("only icp_method 'color' and global_registration 'ransac' are recorded")
    return config


def out(config, name):
    return os.path.join(config["path_output"], name)


def clean_folder(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)


def rgbd_files(config, n_max):
    root = config["path_dataset"]
    colour_dir = next(os.path.join(root, d) for d in ("image", "rgb", "color") if os.path.isdir(os.path.join(root, d)))
    colours = sorted(glob.glob(os.path.join(colour_dir, "*.jpg"))) + sorted(glob.glob(os.path.join(colour_dir, "*.png")))
    depths = sorted(glob.glob(os.path.join(root, "depth", "*.png")))
    n = min(len(colours), len(depths), n_max or 1 << 30)
    return colours[:n], depths[:n]


def intrinsic_of(config):
    if config["path_intrinsic"]:
        return o3d.io.read_pinhole_camera_intrinsic(config["path_intrinsic"])
    return o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)


def read_rgbd(colour, depth, to_intensity, config):
    return o3d.geometry.RGBDImage.create_from_color_and_depth(
        o3d.io.read_image(colour), o3d.io.read_image(depth), depth_scale=config["depth_scale"],
        depth_trunc=config["depth_max"], convert_rgb_to_intensity=to_intensity)


def optimize(src, dst, max_distance, preference):
    graph = o3d.io.read_pose_graph(src)
    option = reg.GlobalOptimizationOption(max_correspondence_distance=max_distance, edge_prune_threshold=0.25,
                                          preference_loop_closure=preference, reference_node=0)
    reg.global_optimization(graph, reg.GlobalOptimizationLevenbergMarquardt(),
                            reg.GlobalOptimizationConvergenceCriteria(), option)
    o3d.io.write_pose_graph(dst, graph)
    return graph


def integrate(frames, intrinsic, config):
    """TSDF of (colour, depth, camera-to-world pose) frames -> legacy mesh with vertex normals (VoxelBlockGrid, see top)."""
    voxel = config["tsdf_cubic_size"] / 512.0
    trunc = 0.04 / voxel  # sdf_trunc 0.04 m, in voxels
    grid = o3d.t.geometry.VoxelBlockGrid(("tsdf", "weight", "color"), (o3c.float32, o3c.float32, o3c.float32),
                                         ((1), (1), (3)), voxel, 16, 50000, o3c.Device("CPU:0"))
    K = o3c.Tensor(intrinsic.intrinsic_matrix, o3c.float64)
    for colour_file, depth_file, pose in frames:
        depth, colour = o3d.t.io.read_image(depth_file), o3d.t.io.read_image(colour_file)
        extrinsic = o3c.Tensor(np.linalg.inv(pose), o3c.float64)
        blocks = grid.compute_unique_block_coordinates(depth, K, extrinsic, config["depth_scale"],
                                                       config["depth_max"], trunc)
        grid.integrate(blocks, depth, colour, K, K, extrinsic, config["depth_scale"], config["depth_max"], trunc)
    mesh = grid.extract_triangle_mesh(weight_threshold=0.0).to_legacy()
    mesh.compute_vertex_normals()
    return mesh


def make_fragments(config, colours, depths, summary):
    clean_folder(out(config, config["folder_fragment"]))
    intrinsic, per = intrinsic_of(config), config["n_frames_per_fragment"]
    n_fragments = int(math.ceil(len(colours) / per))
    option = o3d.pipelines.odometry.OdometryOption()
    option.depth_diff_max = config["depth_diff_max"]
    detail, failed, points = {"odometry": 0.0, "optimize": 0.0, "tsdf": 0.0}, [], []
    for f in range(n_fragments):
        sid, eid = f * per, min(f * per + per, len(colours))
        t0 = time.perf_counter()
        graph, odometry = reg.PoseGraph(), np.identity(4)
        graph.nodes.append(reg.PoseGraphNode(odometry))
        for s in range(sid, eid - 1):
            # Only neighbouring frames: keyframe pairs need OpenCV's 5-point init, which Open3D skips without it.
            # Both images are read per pair, as Open3D does (it matters for the timing).
            source = read_rgbd(colours[s], depths[s], True, config)
            target = read_rgbd(colours[s + 1], depths[s + 1], True, config)
            ok, trans, info = o3d.pipelines.odometry.compute_rgbd_odometry(
                source, target, intrinsic, np.identity(4),
                o3d.pipelines.odometry.RGBDOdometryJacobianFromHybridTerm(), option)
            if not ok:
                failed.append([s, s + 1])  # Open3D keeps the edge anyway
            odometry = trans @ odometry
            graph.nodes.append(reg.PoseGraphNode(np.linalg.inv(odometry)))
            graph.edges.append(reg.PoseGraphEdge(s - sid, s + 1 - sid, trans, info, uncertain=False))
        o3d.io.write_pose_graph(out(config, config["template_fragment_posegraph"] % f), graph)
        t1 = time.perf_counter()
        graph = optimize(out(config, config["template_fragment_posegraph"] % f),
                         out(config, config["template_fragment_posegraph_optimized"] % f),
                         config["depth_diff_max"], config["preference_loop_closure_odometry"])
        t2 = time.perf_counter()
        mesh = integrate([(colours[sid + i], depths[sid + i], n.pose) for i, n in enumerate(graph.nodes)],
                         intrinsic, config)
        pcd = o3d.geometry.PointCloud()
        pcd.points, pcd.colors = mesh.vertices, mesh.vertex_colors
        if config["fragment_normals"]:
            pcd.normals = mesh.vertex_normals
        o3d.io.write_point_cloud(out(config, config["template_fragment_pointcloud"] % f), pcd,
                                 write_ascii=False, compressed=True)
        t3 = time.perf_counter()
        detail["odometry"] += t1 - t0; detail["optimize"] += t2 - t1; detail["tsdf"] += t3 - t2
        points.append(len(pcd.points))
        print("fragment %d: frames %d-%d, %d points" % (f, sid, eid - 1, len(pcd.points)), flush=True)
    summary.update(n_fragments=n_fragments, fragment_points=points, odometry_failed_pairs=failed,
                   make_seconds_detail=detail)


def fragment_files(config):
    return sorted(glob.glob(os.path.join(out(config, config["folder_fragment"]), "*.ply")))


def multiscale_icp(source, target, voxels, iterations, init):
    """Colored ICP coarse to fine; the information matrix comes from the last scale's clouds."""
    trans = init
    for voxel, iters in zip(voxels, iterations):
        src, tgt = source.voxel_down_sample(voxel), target.voxel_down_sample(voxel)
        for cloud in (src, tgt):
            cloud.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2.0 * voxel, max_nn=30))
        # Open3D passes the scale's voxel as the distance (colored ICP is sensitive to it)
        trans = reg.registration_colored_icp(src, tgt, voxel, trans, reg.TransformationEstimationForColoredICP(),
                                             reg.ICPConvergenceCriteria(1e-6, 1e-6, iters)).transformation
    info = reg.get_information_matrix_from_point_clouds(src, tgt, 1.4 * voxels[-1], trans)
    return trans, info


def preprocess(path, voxel):
    down = o3d.io.read_point_cloud(path).voxel_down_sample(voxel)
    down.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2.0 * voxel, max_nn=30))
    fpfh = reg.compute_fpfh_feature(down, o3d.geometry.KDTreeSearchParamHybrid(radius=5.0 * voxel, max_nn=100))
    return down, fpfh


def ransac(source, target, source_fpfh, target_fpfh, voxel):
    distance = 1.4 * voxel
    result = reg.registration_ransac_based_on_feature_matching(
        source, target, source_fpfh, target_fpfh, False, distance, reg.TransformationEstimationPointToPoint(False),
        4, [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(distance)],
        reg.RANSACConvergenceCriteria(1000000, 0.999))
    if np.trace(result.transformation) == 4.0:  # RANSAC found nothing
        return None
    info = reg.get_information_matrix_from_point_clouds(source, target, distance, result.transformation)
    if info[5, 5] / min(len(source.points), len(target.points)) < 0.3:  # too little overlap
        return None
    return result.transformation, info


def scene_graph(matches):
    """Adjacent pairs chain the nodes and are certain; the rest are uncertain loop closures."""
    graph, odometry = reg.PoseGraph(), np.identity(4)
    graph.nodes.append(reg.PoseGraphNode(odometry))
    for s, t, trans, info in matches:
        if t == s + 1:
            odometry = trans @ odometry
            graph.nodes.append(reg.PoseGraphNode(np.linalg.inv(odometry)))
        graph.edges.append(reg.PoseGraphEdge(s, t, trans, info, uncertain=t != s + 1))
    return graph


def edges_of(graph):
    return [[e.source_node_id, e.target_node_id, bool(e.uncertain)] for e in graph.edges]


def register_fragments(config, summary):
    clean_folder(out(config, config["folder_scene"]))
    files, voxel, matches = fragment_files(config), config["voxel_size"], []
    for s in range(len(files)):
        for t in range(s + 1, len(files)):
            # Open3D reads and preprocesses both fragments again for every pair
            (src, src_fpfh), (tgt, tgt_fpfh) = preprocess(files[s], voxel), preprocess(files[t], voxel)
            if t == s + 1:  # start from the odometry across the fragment's end
                last = o3d.io.read_pose_graph(out(config, config["template_fragment_posegraph_optimized"] % s))
                found = multiscale_icp(src, tgt, [voxel], [50], np.linalg.inv(last.nodes[-1].pose))
            else:
                found = ransac(src, tgt, src_fpfh, tgt_fpfh, voxel)
            print("register %d-%d: %s" % (s, t, "ok" if found else "no reasonable solution"), flush=True)
            if found:
                matches.append((s, t) + tuple(found))
    o3d.io.write_pose_graph(out(config, config["template_global_posegraph"]), scene_graph(matches))
    graph = optimize(out(config, config["template_global_posegraph"]),
                     out(config, config["template_global_posegraph_optimized"]),
                     1.4 * voxel, config["preference_loop_closure_registration"])
    summary.update(global_edges_before_pruning=[[s, t, t != s + 1] for s, t, _, _ in matches],
                   global_edges_kept=edges_of(graph))


def refine_registration(config, summary):
    files, voxel = fragment_files(config), config["voxel_size"]
    rough = o3d.io.read_pose_graph(out(config, config["template_global_posegraph_optimized"]))
    matches = []
    for e in rough.edges:  # the edges the global optimization kept, in order
        s, t = e.source_node_id, e.target_node_id
        source, target = o3d.io.read_point_cloud(files[s]), o3d.io.read_point_cloud(files[t])
        trans, info = multiscale_icp(source, target, [voxel, voxel / 2.0, voxel / 4.0], [50, 30, 14], e.transformation)
        matches.append((s, t, trans, info))
    o3d.io.write_pose_graph(out(config, config["template_refined_posegraph"]), scene_graph(matches))
    graph = optimize(out(config, config["template_refined_posegraph"]),
                     out(config, config["template_refined_posegraph_optimized"]),
                     1.4 * voxel, config["preference_loop_closure_registration"])
    summary.update(refined_edges_kept=edges_of(graph))


def integrate_scene(config, colours, depths, summary):
    scene = o3d.io.read_pose_graph(out(config, config["template_refined_posegraph_optimized"]))
    frames = []
    for f, node in enumerate(scene.nodes):
        fragment = o3d.io.read_pose_graph(out(config, config["template_fragment_posegraph_optimized"] % f))
        for i, frame in enumerate(fragment.nodes):
            k = f * config["n_frames_per_fragment"] + i
            frames.append((colours[k], depths[k], node.pose @ frame.pose))
    mesh = integrate(frames, intrinsic_of(config), config)
    o3d.io.write_triangle_mesh(out(config, config["template_global_mesh"]), mesh, write_ascii=False, compressed=True)
    with open(out(config, config["template_global_traj"]), "w") as log:  # write_pinhole_camera_trajectory's .log
        for i, (_, _, pose) in enumerate(frames):
            log.write("%d %d %d\n" % (i, i, i + 1))
            log.write("".join("%.8f %.8f %.8f %.8f\n" % tuple(row) for row in pose))
    summary.update(scene_mesh={"vertices": len(mesh.vertices), "triangles": len(mesh.triangles)},
                   poses_camera_to_world=[[float(x) for x in pose.reshape(-1)] for _, _, pose in frames])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--config", required=True)
    for stage in ("make", "register", "refine", "integrate"):
        parser.add_argument("--" + stage, action="store_true")
    parser.add_argument("--summary")
    parser.add_argument("--frames", type=int, default=0, help="use only the first N frames")
    parser.add_argument("--note", help="stored as timing_note (e.g. how loaded the machine was)")
    args = parser.parse_args()
    config = load_config(args.config)
    os.makedirs(config["path_output"], exist_ok=True)
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
    o3d.utility.random.seed(0)
    colours, depths = rgbd_files(config, args.frames)
    summary = {"open3d_version": o3d.__version__, "config": config, "n_frames": len(colours),
               "n_fragments": int(math.ceil(len(colours) / config["n_frames_per_fragment"])), "seconds": {}}
    if args.note:
        summary["timing_note"] = args.note
    stages = [("make", lambda: make_fragments(config, colours, depths, summary)),
              ("register", lambda: register_fragments(config, summary)),
              ("refine", lambda: refine_registration(config, summary)),
              ("integrate", lambda: integrate_scene(config, colours, depths, summary))]
    for name, run in stages:
        if getattr(args, name):
            start = time.perf_counter()
            run()
            summary["seconds"][name] = time.perf_counter() - start
            print("%s: %.2f s" % (name, summary["seconds"][name]), flush=True)
    if args.summary:
        with open(args.summary, "w") as f:
            json.dump(summary, f, indent=1)


if __name__ == "__main__":
    main()
