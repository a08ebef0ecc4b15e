#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference numbers from Open3D 0.20 for bindings/python/tests/test_feature.py, test_pose_graph.py,
test_icp_variants.py and test_open3d_compat_registration.py.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_python_registration.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout. Each printed line is a value a
test compares against (the test cites the name). Fingerprints: fp(a) = sum_i (i + 1) * a_i over the
flattened array (so order and values must match).
"""
import os
import pathlib
import sys

import numpy as np
import open3d as o3d

reg = o3d.pipelines.registration
HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parents[1]


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    return os.environ.get("O3D_TEST_DATA", str(REPO / ".." / "shared" / "data"))


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def show(name, value):
    print(f"{name} = {value!r}")


def matching_share(points0, feature0, points1, feature1, within=0.075):
    """Share of cloud 1's points whose nearest descriptor in cloud 0 belongs to a point within `within`."""
    tree = o3d.geometry.KDTreeFlann(feature0)
    f1 = np.asarray(feature1.data)
    hits = 0
    for j in range(f1.shape[1]):
        _, idx, _ = tree.search_knn_vector_xd(f1[:, j], 1)
        hits += np.linalg.norm(points0[idx[0]] - points1[j]) < within
    return hits / f1.shape[1]


def synthetic_pose_graph():
    """The test's synthetic loop (test_pose_graph.py, make_loop_graph): 6 poses on a circle, odometry edges
    with exact relative motions, one exact loop closure 5 -> 0 and one false loop closure 3 -> 0."""
    def pose(k):
        a = k * np.pi / 3.0
        t = np.eye(4)
        t[:3, :3] = [[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]]
        t[:3, 3] = [2.0 * np.cos(a), 2.0 * np.sin(a), 0.1 * k]
        return t

    poses = [pose(k) for k in range(6)]
    info = np.diag([400.0, 400.0, 400.0, 100.0, 100.0, 100.0])
    graph = reg.PoseGraph()
    drift = np.eye(4)
    drift[:3, 3] = [0.02, -0.01, 0.015]
    for k, p in enumerate(poses):
        graph.nodes.append(reg.PoseGraphNode(p @ np.linalg.matrix_power(drift, k)))
    for k in range(5):
        rel = np.linalg.inv(poses[k + 1]) @ poses[k]
        graph.edges.append(reg.PoseGraphEdge(k, k + 1, rel, info, uncertain=False))
    graph.edges.append(reg.PoseGraphEdge(5, 0, np.linalg.inv(poses[0]) @ poses[5], info, uncertain=True))
    false = np.eye(4)
    false[:3, 3] = [1.5, -0.7, 0.4]
    graph.edges.append(reg.PoseGraphEdge(3, 0, false, info, uncertain=True))
    return graph, poses


def main():
    root = pathlib.Path(data_root())
    feature = root / "open3d" / "Feature"
    print(f"# Open3D {o3d.__version__}, numpy {np.__version__}")

    # ---- stored features
    f0 = o3d.io.read_feature(str(feature / "cloud_bin_0.fpfh.bin"))
    f1 = o3d.io.read_feature(str(feature / "cloud_bin_1.fpfh.bin"))
    for name, f in (("stored0", f0), ("stored1", f1)):
        d = np.asarray(f.data)
        show(f"{name}.shape", d.shape)
        show(f"{name}.fp", fp(d))
        show(f"{name}.column0", d[:, 0].tolist())

    # ---- our inputs: the Feature clouds with their stored normals
    c0 = o3d.io.read_point_cloud(str(feature / "cloud_bin_0.pcd"))
    c1 = o3d.io.read_point_cloud(str(feature / "cloud_bin_1.pcd"))
    p0, p1 = np.asarray(c0.points), np.asarray(c1.points)
    show("cloud0.size", len(p0))
    show("cloud1.size", len(p1))
    param = o3d.geometry.KDTreeSearchParamHybrid(radius=0.25, max_nn=100)
    fpfh0 = reg.compute_fpfh_feature(c0, param)
    fpfh1 = reg.compute_fpfh_feature(c1, param)
    d0 = np.asarray(fpfh0.data)
    show("fpfh0.shape", d0.shape)
    show("fpfh0.fp", fp(d0))
    show("fpfh0.sum", float(d0.sum()))
    show("fpfh0.column0", d0[:, 0].tolist())
    show("fpfh0.column1000", d0[:, 1000].tolist())
    sub = reg.compute_fpfh_feature(c0, param, [5, 1000, 17])
    show("fpfh0_indices.fp", fp(np.asarray(sub.data)))
    knn = reg.compute_fpfh_feature(c0, o3d.geometry.KDTreeSearchParamKNN(30))
    show("fpfh0_knn30.fp", fp(np.asarray(knn.data)))

    # ---- matching quality (share of cloud 1's points matched within 0.075 m)
    show("matching.stored", matching_share(p0, f0, p1, f1))
    show("matching.fpfh_r025", matching_share(p0, fpfh0, p1, fpfh1))

    # ---- correspondences from the stored features
    for mutual in (False, True):
        c = np.asarray(reg.correspondences_from_features(f0, f1, mutual))
        show(f"corres.mutual={mutual}.n", len(c))
        show(f"corres.mutual={mutual}.fp", fp(c))

    # ---- robust kernel weights
    residuals = [0.0, 0.3, 1.0, 2.5]
    for name, kernel in (("L2", reg.L2Loss()), ("L1", reg.L1Loss()), ("Huber", reg.HuberLoss(k=1.0)),
                         ("Cauchy", reg.CauchyLoss(k=0.5)), ("GM", reg.GMLoss(k=0.5)), ("Tukey", reg.TukeyLoss(k=2.0))):
        show(f"kernel.{name}", [kernel.weight(r) for r in residuals[1:]])

    # ---- synthetic pose graph with a false loop closure
    graph, _ = synthetic_pose_graph()
    reg.global_optimization(graph, reg.GlobalOptimizationLevenbergMarquardt(),
                            reg.GlobalOptimizationConvergenceCriteria(),
                            reg.GlobalOptimizationOption(max_correspondence_distance=0.075, edge_prune_threshold=0.25,
                                                         preference_loop_closure=1.0, reference_node=0))
    show("posegraph.edges_after", len(graph.edges))
    show("posegraph.kept_pairs", [(e.source_node_id, e.target_node_id) for e in graph.edges])
    show("posegraph.poses_fp", fp(np.array([n.pose for n in graph.nodes])))

    # ---- the compat script (Open3D's global-registration tutorial), run with Open3D
    script = REPO / "bindings" / "python" / "tests" / "compat_scripts" / "global_registration_tutorial.py"
    ns = {"open3d": o3d, "np": np, "result": {}, "DATA": str(root / "open3d")}
    exec(compile(script.read_text(), str(script), "exec"), ns)
    show("compat.result", ns["result"])

    # ---- examples/python/multiway_registration.py run with Open3D as `o3d` (default frames and voxel)
    import contextlib
    import io
    import runpy

    o3d.O3DError = RuntimeError  # the example's except clause
    sys.modules["o3d"] = o3d
    out = io.StringIO()
    argv, sys.argv = sys.argv, ["multiway_registration.py", str(root / "livingroom1_clean_micro")]
    with contextlib.redirect_stdout(out):
        try:
            runpy.run_path(str(REPO / "examples" / "python" / "multiway_registration.py"), run_name="__main__")
        except SystemExit:
            pass
    sys.argv = argv
    for line in out.getvalue().splitlines():
        if line.startswith(("optimized:", "pose ")):
            print(f"multiway: {line}")


if __name__ == "__main__":
    main()
