#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's global_optimization results, for tests/core/global_optimization_reference_test.cpp.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_pose_graph.py [DATA_ROOT]          # the numbers
    /tmp/o3dref/bin/python tools/reference/record_pose_graph.py --time [NODES]       # Open3D's timing
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout. (The wheel's libOpen3D needs
libusb-1.0.so.0; without the Debian package, extract it and point LD_LIBRARY_PATH at it.)

Two graphs:
- test_pose_graph.json from Open3D's test data: 2 nodes, 2 edges, random matrices, and its second edge
  names node 2, which does not exist. Open3D's global_optimization refuses it (a warning) and leaves it
  unchanged; we print its first node and edge as read, to pin down the column-major layout.
- "ring": a well-formed graph built here from closed formulas (no RNG), so that the C++ test builds it
  bit for bit the same way (tests/core/global_optimization_reference_test.cpp, make_ring): N poses on a
  circle, noisy odometry edges i -> i+1 (certain), and uncertain loop closures: (N-1 -> 0), (i+3 -> i)
  every third i, and one false closure (N/2 -> 1) whose measurement is off by 0.8 rad and ~0.8 m.
  Every edge has the information matrix of the same 100 synthetic point pairs (Lambda(5, 5) = 100).
"""
import math
import os
import sys
import time

import numpy as np
import open3d as o3d

reg = o3d.pipelines.registration


def data_root():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if args:
        return args[0]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rigid(r, t):
    m = np.identity(4)
    m[:3, :3] = r
    m[:3, 3] = t
    return m


def rigid_inverse(m):
    r = m[:3, :3].T
    return rigid(r, -r @ m[:3, 3])


def rodrigues(w):
    theta = math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    k = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]]) / theta
    return np.identity(3) + math.sin(theta) * k + (1.0 - math.cos(theta)) * (k @ k)


def ground_truth(i, n):
    th = 2.0 * math.pi * i / n
    return rigid(rot_z(th) @ rot_x(0.1 * math.sin(3.0 * th)),
                 [2.0 * math.cos(th) - 2.0, 2.0 * math.sin(th), 0.2 * math.sin(2.0 * th)])


def noise(k):
    w = [0.01 * math.sin(1.3 * k + 0.1), 0.01 * math.cos(2.1 * k + 0.2), 0.01 * math.sin(0.7 * k + 0.3)]
    t = [0.01 * math.cos(1.1 * k), 0.01 * math.sin(1.9 * k + 0.5), 0.01 * math.cos(0.3 * k + 0.7)]
    return rigid(rodrigues(w), t)


def information():
    info = np.zeros((6, 6))
    for k in range(100):
        x = 2.0 * math.fmod(0.5 + k * 0.7548776662466927, 1.0) - 1.0
        y = 2.0 * math.fmod(0.5 + k * 0.5698402909980532, 1.0) - 1.0
        z = 0.25 * math.sin(3.0 * x) * math.cos(2.0 * y)
        for g in ([0.0, z, -y, 1.0, 0.0, 0.0], [-z, 0.0, x, 0.0, 1.0, 0.0], [y, -x, 0.0, 0.0, 0.0, 1.0]):
            g = np.array(g)
            info += np.outer(g, g)
    return info


def ring_edges(n):
    """(source, target, uncertain, false) in the order the graph lists them."""
    edges = [(i, i + 1, False, False) for i in range(n - 1)]
    edges.append((n - 1, 0, True, False))
    edges += [(i + 3, i, True, False) for i in range(0, n - 3, 3)]
    edges.append((n // 2, 1, True, True))
    return edges


def make_ring(n):
    gt = [ground_truth(i, n) for i in range(n)]
    info = information()
    wrong = rigid(rot_z(0.8), [0.6, -0.4, 0.3])
    graph = reg.PoseGraph()
    measured = {}
    for k, (s, t, uncertain, false) in enumerate(ring_edges(n)):
        m = noise(k) @ (rigid_inverse(gt[t]) @ gt[s])
        if false:
            m = wrong @ m
        measured[(s, t)] = m
        graph.edges.append(reg.PoseGraphEdge(s, t, m, info, uncertain=uncertain))
    # Nodes from the odometry chain, as the reconstruction system does: pose_t = pose_s T^-1.
    pose = np.identity(4)
    graph.nodes.append(reg.PoseGraphNode(pose))
    for i in range(n - 1):
        pose = pose @ rigid_inverse(measured[(i, i + 1)])
        graph.nodes.append(reg.PoseGraphNode(pose))
    return graph


def c_array(name, values):
    body = ", ".join(repr(float(v)) for v in values)
    print(f"constexpr double {name}[] = {{{body}}};")


def optimize(graph, method, reference_node=-1):
    option = reg.GlobalOptimizationOption(max_correspondence_distance=0.075, edge_prune_threshold=0.25,
                                          preference_loop_closure=1.0, reference_node=reference_node)
    reg.global_optimization(graph, method, reg.GlobalOptimizationConvergenceCriteria(), option)
    return graph


def show_result(tag, graph):
    print(f"// {tag}: {len(graph.nodes)} nodes, {len(graph.edges)} edges left")
    print(f"constexpr size_t k{tag}Edges = {len(graph.edges)};")
    ids = ", ".join(str(v) for e in graph.edges for v in (e.source_node_id, e.target_node_id))
    print(f"constexpr int k{tag}EdgeIds[] = {{{ids}}};")
    c_array(f"k{tag}Confidence", [e.confidence for e in graph.edges])
    c_array(f"k{tag}Poses", [v for node in graph.nodes for v in np.asarray(node.pose).ravel()])


def record(root):
    print(f"// Open3D {o3d.__version__}, numpy {np.__version__}")
    graph = o3d.io.read_pose_graph(os.path.join(root, "open3d", "test_pose_graph.json"))
    print(f"// test_pose_graph.json: {len(graph.nodes)} nodes, {len(graph.edges)} edges")
    c_array("kFileNode0", np.asarray(graph.nodes[0].pose).ravel())
    c_array("kFileEdge0Transformation", np.asarray(graph.edges[0].transformation).ravel())
    c_array("kFileEdge0Information", np.asarray(graph.edges[0].information).ravel())
    before = [np.asarray(n.pose).copy() for n in graph.nodes]
    optimize(graph, reg.GlobalOptimizationLevenbergMarquardt())
    unchanged = all(np.array_equal(b, np.asarray(n.pose)) for b, n in zip(before, graph.nodes))
    print(f"// after global_optimization: {len(graph.edges)} edges, poses unchanged: {unchanged}")

    n = 8
    ring = make_ring(n)
    print(f"// ring({n}) as built: node {n - 1} pose and the false closure's measurement")
    c_array("kRingNode7", np.asarray(ring.nodes[n - 1].pose).ravel())
    c_array("kRingFalseClosure", np.asarray(ring.edges[-1].transformation).ravel())
    show_result("RingLM", optimize(make_ring(n), reg.GlobalOptimizationLevenbergMarquardt()))
    show_result("RingGN", optimize(make_ring(n), reg.GlobalOptimizationGaussNewton()))
    show_result("RingLMRef0", optimize(make_ring(n), reg.GlobalOptimizationLevenbergMarquardt(), 0))
    show_result("RingGNRef3", optimize(make_ring(n), reg.GlobalOptimizationGaussNewton(), 3))


def timing(n):
    """Median of repeated global_optimization calls on ring(n) (the graph rebuilt outside the timer)."""
    methods = (("LM", reg.GlobalOptimizationLevenbergMarquardt()), ("GN", reg.GlobalOptimizationGaussNewton()))
    for name, method in methods:
        times = []
        for _ in range(21 if n <= 100 else 5):
            g = make_ring(n)
            t0 = time.perf_counter()
            optimize(g, method)
            times.append(time.perf_counter() - t0)
        print(f"ring({n}) {name}: median {1e3 * sorted(times)[len(times) // 2]:.3f} ms, {len(g.edges)} edges left")


if __name__ == "__main__":
    if "--time" in sys.argv:
        rest = [a for a in sys.argv[1:] if not a.startswith("--")]
        for n in ([int(rest[0])] if rest else [8, 100, 1000]):
            timing(n)
    else:
        record(data_root())
