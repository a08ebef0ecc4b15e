#!/usr/bin/env python3
"""Multiway registration, as Open3D's tutorial, over scans made from an RGB-D sequence.

usage: multiway_registration.py DATA_DIR [FRAMES=0,10,20,30,40] [VOXEL=0.05]

DATA_DIR holds image/NNNNN.jpg and depth/NNNNN.png (16-bit millimetres), e.g. livingroom1_clean_micro. Each
listed frame is back-projected with the PrimeSense intrinsics (640x480, fx = fy = 525) and voxel-down-sampled;
every pair is registered with point-to-plane ICP, coarse then fine, and its information matrix computed.
Consecutive pairs become odometry edges, the others uncertain loop closures; global_optimization
(Levenberg-Marquardt, line process) then optimizes the poses and prunes loop closures it does not trust.
Prints the optimized poses (row-major, one line each). Exits 1 when the optimized graph disagrees with its odometry, 2 on bad usage.
Same calls as Open3D's, with `import o3d`.
"""
import os
import sys
import time

import numpy as np

import o3d

reg = o3d.pipelines.registration


def load_scans(data_dir, frames, voxel_size):
    intrinsic = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    scans = []
    for frame in frames:
        color = o3d.io.read_image(os.path.join(data_dir, "image", f"{frame:05d}.jpg"))
        depth = o3d.io.read_image(os.path.join(data_dir, "depth", f"{frame:05d}.png"))
        rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth, depth_trunc=3.0,
                                                                  convert_rgb_to_intensity=False)
        pcd = o3d.geometry.PointCloud.create_from_rgbd_image(rgbd, intrinsic).voxel_down_sample(voxel_size)
        pcd.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=voxel_size * 2, max_nn=30))
        scans.append(pcd)
    return scans


def pairwise_registration(source, target, max_correspondence_distance_coarse, max_correspondence_distance_fine):
    icp_coarse = reg.registration_icp(source, target, max_correspondence_distance_coarse, np.identity(4),
                                      reg.TransformationEstimationPointToPlane())
    icp_fine = reg.registration_icp(source, target, max_correspondence_distance_fine, icp_coarse.transformation,
                                    reg.TransformationEstimationPointToPlane())
    information = reg.get_information_matrix_from_point_clouds(source, target, max_correspondence_distance_fine,
                                                                icp_fine.transformation)
    return icp_fine.transformation, information


def full_registration(scans, max_correspondence_distance_coarse, max_correspondence_distance_fine):
    pose_graph = reg.PoseGraph()
    odometry = np.identity(4)
    pose_graph.nodes.append(reg.PoseGraphNode(odometry))
    for source_id in range(len(scans)):
        for target_id in range(source_id + 1, len(scans)):
            transformation, information = pairwise_registration(scans[source_id], scans[target_id],
                                                                max_correspondence_distance_coarse,
                                                                max_correspondence_distance_fine)
            if target_id == source_id + 1:  # odometry
                odometry = transformation @ odometry
                pose_graph.nodes.append(reg.PoseGraphNode(np.linalg.inv(odometry)))
                pose_graph.edges.append(reg.PoseGraphEdge(source_id, target_id, transformation, information,
                                                          uncertain=False))
            else:  # loop closure
                pose_graph.edges.append(reg.PoseGraphEdge(source_id, target_id, transformation, information,
                                                          uncertain=True))
    return pose_graph


def odometry_disagreement(pose_graph):
    """Largest rotation (degrees) and translation (metres) between an odometry edge and the optimized poses."""
    worst_angle = worst_shift = 0.0
    for edge in pose_graph.edges:
        if edge.uncertain:
            continue
        source = pose_graph.nodes[edge.source_node_id].pose
        target = pose_graph.nodes[edge.target_node_id].pose
        delta = np.linalg.inv(edge.transformation) @ np.linalg.inv(target) @ source
        cos = np.clip((np.trace(delta[:3, :3]) - 1.0) / 2.0, -1.0, 1.0)
        worst_angle = max(worst_angle, float(np.degrees(np.arccos(cos))))
        worst_shift = max(worst_shift, float(np.linalg.norm(delta[:3, 3])))
    return worst_angle, worst_shift


def main(argv):
    if len(argv) not in (2, 3, 4):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    data_dir = argv[1]
    try:
        frames = [int(f) for f in argv[2].split(",")] if len(argv) > 2 else [0, 10, 20, 30, 40]
        voxel_size = float(argv[3]) if len(argv) > 3 else 0.05
    except ValueError:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    if len(frames) < 2 or not voxel_size > 0:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    scans = load_scans(data_dir, frames, voxel_size)
    print(f"{len(scans)} scans (frames {frames}), voxel {voxel_size}: "
          f"{', '.join(str(len(s.points)) for s in scans)} points")

    max_correspondence_distance_coarse = voxel_size * 15
    max_correspondence_distance_fine = voxel_size * 1.5
    pose_graph = full_registration(scans, max_correspondence_distance_coarse, max_correspondence_distance_fine)
    n_edges = len(pose_graph.edges)
    print(f"pose graph: {len(pose_graph.nodes)} nodes, {n_edges} edges "
          f"({sum(1 for e in pose_graph.edges if e.uncertain)} loop closures)")

    option = reg.GlobalOptimizationOption(max_correspondence_distance=max_correspondence_distance_fine,
                                          edge_prune_threshold=0.25, preference_loop_closure=1.0, reference_node=0)
    reg.global_optimization(pose_graph, reg.GlobalOptimizationLevenbergMarquardt(),
                            reg.GlobalOptimizationConvergenceCriteria(), option)
    print(f"optimized: {len(pose_graph.edges)} edges kept ({n_edges - len(pose_graph.edges)} loop closures pruned)")
    for i, node in enumerate(pose_graph.nodes):
        print(f"pose {i} (frame {frames[i]}): {np.round(node.pose, 4).tolist()}")
    angle, shift = odometry_disagreement(pose_graph)
    print(f"odometry disagreement: {angle:.3f} deg, {shift * 1000:.1f} mm")
    print(f"done in {time.perf_counter() - t0:.2f} s (o3d {o3d.__version__})")
    poses = np.array([node.pose for node in pose_graph.nodes])
    if not np.all(np.isfinite(poses)) or angle > 5.0 or shift > 0.1:
        print("error: the optimized poses disagree with the odometry", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
