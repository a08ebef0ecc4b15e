#!/usr/bin/env python3
"""Compare two reconstruction-system outputs (e.g. o3d's and record_reconstruction.py's): camera poses, scene mesh
size and mesh-to-mesh distances, and how well the refined fragment pairs fit (inlier RMSE within 5 cm).

    bench/.venv/bin/python tools/reference/compare_reconstruction.py OUTPUT_A OUTPUT_B

Each OUTPUT is a path_output folder (fragments/ and scene/). Uses the Open3D wheel only to read and measure.
"""
import sys

import numpy as np
import open3d as o3d


def angle(a, b):
    d = np.linalg.inv(a) @ b
    return np.degrees(np.arccos(np.clip((np.trace(d[:3, :3]) - 1) / 2, -1, 1)))


def poses(folder):
    trajectory = o3d.io.read_pinhole_camera_trajectory(folder + "/scene/trajectory.log")
    return [np.linalg.inv(p.extrinsic) for p in trajectory.parameters]


def pair_fit(folder):
    graph = o3d.io.read_pose_graph(folder + "/scene/refined_registration_optimized.json")
    clouds = [o3d.io.read_point_cloud(f"{folder}/fragments/fragment_{i:03d}.ply").voxel_down_sample(0.02)
              for i in range(len(graph.nodes))]
    fits = []
    for e in graph.edges:
        s, t = e.source_node_id, e.target_node_id
        relative = np.linalg.inv(graph.nodes[t].pose) @ graph.nodes[s].pose
        r = o3d.pipelines.registration.evaluate_registration(clouds[s], clouds[t], 0.05, relative)
        fits.append(f"{s}->{t}: fitness {r.fitness:.3f}, RMSE {1000 * r.inlier_rmse:.1f} mm")
    return fits


def main(a, b):
    pa, pb = poses(a), poses(b)
    dt = [np.linalg.norm(x[:3, 3] - y[:3, 3]) for x, y in zip(pa, pb)]
    dr = [angle(x, y) for x, y in zip(pa, pb)]
    print(f"poses: {len(pa)} / {len(pb)}; camera centres apart median {1000 * np.median(dt):.1f} mm, max "
          f"{1000 * max(dt):.1f} mm; rotations apart median {np.median(dr):.3f}, max {max(dr):.3f} degrees")
    ma = o3d.io.read_triangle_mesh(a + "/scene/integrated.ply")
    mb = o3d.io.read_triangle_mesh(b + "/scene/integrated.ply")
    print(f"scene mesh vertices {len(ma.vertices):,} / {len(mb.vertices):,}, triangles {len(ma.triangles):,} / "
          f"{len(mb.triangles):,}")
    ca, cb = o3d.geometry.PointCloud(ma.vertices), o3d.geometry.PointCloud(mb.vertices)
    ab, ba = np.asarray(ca.compute_point_cloud_distance(cb)), np.asarray(cb.compute_point_cloud_distance(ca))
    print(f"mesh distance a->b median {1000 * np.median(ab):.1f} mm (90%: {1000 * np.quantile(ab, 0.9):.1f}); "
          f"b->a median {1000 * np.median(ba):.1f} mm (90%: {1000 * np.quantile(ba, 0.9):.1f})")
    for name, folder in (("a", a), ("b", b)):
        print(f"refined fragment pairs of {name}: " + "; ".join(pair_fit(folder)))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
