"""PoseGraph / PoseGraphNode / PoseGraphEdge (list-like nodes and edges that read and write the graph, as
Open3D's), read/write_pose_graph, and global_optimization. Reference numbers: Open3D 0.20 through
tools/reference/record_python_registration.py (posegraph.*)."""
import copy
import json
import pickle

import numpy as np
import pytest

import o3d
from o3d.pipelines import registration as reg


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def translation(x, y, z):
    t = np.eye(4)
    t[:3, 3] = [x, y, z]
    return t


def circle_pose(k):
    a = k * np.pi / 3.0
    t = np.eye(4)
    t[:3, :3] = [[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]]
    t[:3, 3] = [2.0 * np.cos(a), 2.0 * np.sin(a), 0.1 * k]
    return t


def make_loop_graph():
    """6 poses on a circle, started with drift; exact odometry, one exact loop closure 5 -> 0 and one false
    loop closure 3 -> 0 (as record_python_registration.py's synthetic_pose_graph)."""
    poses = [circle_pose(k) for k in range(6)]
    info = np.diag([400.0, 400.0, 400.0, 100.0, 100.0, 100.0])
    graph = reg.PoseGraph()
    drift = translation(0.02, -0.01, 0.015)
    for k, p in enumerate(poses):
        graph.nodes.append(reg.PoseGraphNode(p @ np.linalg.matrix_power(drift, k)))
    for k in range(5):
        graph.edges.append(reg.PoseGraphEdge(k, k + 1, np.linalg.inv(poses[k + 1]) @ poses[k], info, uncertain=False))
    graph.edges.append(reg.PoseGraphEdge(5, 0, np.linalg.inv(poses[0]) @ poses[5], info, uncertain=True))
    graph.edges.append(reg.PoseGraphEdge(3, 0, translation(1.5, -0.7, 0.4), info, uncertain=True))
    return graph, poses


OPTION = reg.GlobalOptimizationOption(max_correspondence_distance=0.075, edge_prune_threshold=0.25,
                                      preference_loop_closure=1.0, reference_node=0)


# ---- values and defaults

def test_node_and_edge_defaults():
    node = reg.PoseGraphNode()
    np.testing.assert_array_equal(node.pose, np.eye(4))
    assert not node.pose.flags.writeable  # as Open3D: assign a new matrix instead
    edge = reg.PoseGraphEdge()
    assert (edge.source_node_id, edge.target_node_id, edge.uncertain, edge.confidence) == (-1, -1, False, 1.0)
    np.testing.assert_array_equal(edge.transformation, np.eye(4))
    np.testing.assert_array_equal(edge.information, np.eye(6))
    assert repr(edge) == "PoseGraphEdge from nodes -1 to -1, access transformation to get relative transformation"
    assert repr(reg.PoseGraph()) == "PoseGraph with 0 nodes and 0 edges."
    criteria = reg.GlobalOptimizationConvergenceCriteria()
    assert (criteria.max_iteration, criteria.min_relative_increment, criteria.min_relative_residual_increment,
            criteria.min_right_term, criteria.min_residual, criteria.max_iteration_lm) == (100, 1e-6, 1e-6, 1e-6, 1e-6, 20)
    assert criteria.upper_scale_factor == pytest.approx(2 / 3) and criteria.lower_scale_factor == pytest.approx(1 / 3)
    option = reg.GlobalOptimizationOption()
    assert (option.max_correspondence_distance, option.edge_prune_threshold, option.preference_loop_closure,
            option.reference_node) == (0.075, 0.25, 1.0, -1)
    # Open3D 0.20's keyword constructor defaults max_correspondence_distance to 0.03 (kept for compatibility)
    assert reg.GlobalOptimizationOption(reference_node=0).max_correspondence_distance == 0.03
    assert isinstance(reg.GlobalOptimizationGaussNewton(), reg.GlobalOptimizationMethod)


def test_build_append_index_iterate():
    graph = reg.PoseGraph()
    for k in range(3):
        graph.nodes.append(reg.PoseGraphNode(translation(k, 0, 0)))
    graph.edges.append(reg.PoseGraphEdge(0, 1, translation(-1, 0, 0), uncertain=False))
    graph.edges.append(reg.PoseGraphEdge(0, 2, translation(-2, 0, 0), uncertain=True, confidence=0.5))
    assert len(graph.nodes) == 3 and len(graph.edges) == 2
    assert repr(graph) == "PoseGraph with 3 nodes and 2 edges."
    assert [n.pose[0, 3] for n in graph.nodes] == [0.0, 1.0, 2.0]
    assert graph.nodes[-1].pose[0, 3] == 2.0
    with pytest.raises(IndexError):
        graph.nodes[3]
    e = graph.edges[1]
    assert (e.source_node_id, e.target_node_id, e.uncertain, e.confidence) == (0, 2, True, 0.5)
    assert [x.target_node_id for x in graph.edges] == [1, 2]
    assert len(graph.nodes[1:]) == 2 and isinstance(graph.nodes[1:], reg.PoseGraphNodeVector)


def test_mutation_writes_through_to_the_graph():
    graph = reg.PoseGraph()
    graph.nodes.append(reg.PoseGraphNode())
    graph.nodes.append(reg.PoseGraphNode())
    graph.edges.append(reg.PoseGraphEdge(0, 1))
    graph.nodes[1].pose = translation(0.0, 3.0, 0.0)
    assert graph.nodes[1].pose[1, 3] == 3.0
    node = graph.nodes[0]
    node.pose = translation(1.0, 0.0, 0.0)  # a view: writes the graph
    assert graph.nodes[0].pose[0, 3] == 1.0
    graph.edges[0].confidence = 0.25
    graph.edges[0].uncertain = True
    graph.edges[0].information = 2.0 * np.eye(6)
    edge = graph.edges[0]
    assert (edge.confidence, edge.uncertain, edge.information[5, 5]) == (0.25, True, 2.0)
    free = reg.PoseGraphNode(translation(0, 0, 7))
    graph.nodes[0] = free  # assignment copies
    free.pose = np.eye(4)
    assert graph.nodes[0].pose[2, 3] == 7.0
    with pytest.raises(ValueError):
        graph.nodes[0].pose[0, 0] = 2.0  # read-only array, as Open3D's
    with pytest.raises(o3d.InvalidArgumentError):
        graph.nodes[0].pose = 2.0 * np.eye(4)  # not a rigid transform
    with pytest.raises(o3d.InvalidArgumentError):
        graph.nodes.append(reg.PoseGraphNode(np.full((4, 4), np.nan)))
    with pytest.raises(TypeError):
        graph.nodes.append(reg.PoseGraphEdge())


def test_assign_insert_delete_and_copies():
    graph = reg.PoseGraph()
    graph.nodes = reg.PoseGraphNodeVector([reg.PoseGraphNode(translation(k, 0, 0)) for k in range(4)])
    graph.edges = [reg.PoseGraphEdge(0, 1), reg.PoseGraphEdge(1, 2)]
    assert (len(graph.nodes), len(graph.edges)) == (4, 2)
    del graph.nodes[0]
    assert [n.pose[0, 3] for n in graph.nodes] == [1.0, 2.0, 3.0] and len(graph.edges) == 2
    graph.nodes.insert(0, reg.PoseGraphNode(translation(9, 0, 0)))
    assert graph.nodes[0].pose[0, 3] == 9.0 and len(graph.nodes) == 4
    graph.edges.pop()
    assert len(graph.edges) == 1
    twin = reg.PoseGraph(graph)
    twin.nodes[0].pose = np.eye(4)
    assert graph.nodes[0].pose[0, 3] == 9.0  # the copy is deep
    for other in (copy.deepcopy(graph), pickle.loads(pickle.dumps(graph))):
        assert len(other.nodes) == 4 and other.nodes[0].pose[0, 3] == 9.0
        assert other.edges[0].target_node_id == 1
    graph.edges.clear()
    assert len(graph.edges) == 0 and len(graph.nodes) == 4


# ---- files

def test_json_round_trip_of_open3d_file(data_file, tmp_path):
    path = data_file("open3d/test_pose_graph.json")
    graph = o3d.io.read_pose_graph(path)
    doc = json.load(open(path))
    assert (len(graph.nodes), len(graph.edges)) == (len(doc["nodes"]), len(doc["edges"])) == (2, 2)
    for node, raw in zip(graph.nodes, doc["nodes"]):  # matrices are column-major in the file
        np.testing.assert_array_equal(node.pose, np.reshape(raw["pose"], (4, 4), order="F"))
    for edge, raw in zip(graph.edges, doc["edges"]):
        assert (edge.source_node_id, edge.target_node_id, edge.uncertain) == (
            raw["source_node_id"], raw["target_node_id"], raw["uncertain"])
        assert edge.confidence == raw.get("confidence", 1.0)  # absent from this file: the default
        np.testing.assert_array_equal(edge.transformation, np.reshape(raw["transformation"], (4, 4), order="F"))
        np.testing.assert_array_equal(edge.information, np.reshape(raw["information"], (6, 6), order="F"))
    out = tmp_path / "graph.json"
    o3d.io.write_pose_graph(str(out), graph)
    back = o3d.io.read_pose_graph(out)
    for a, b in zip(graph.nodes, back.nodes):
        np.testing.assert_array_equal(a.pose, b.pose)
    for a, b in zip(graph.edges, back.edges):
        np.testing.assert_array_equal(a.transformation, b.transformation)
        np.testing.assert_array_equal(a.information, b.information)
        assert (a.source_node_id, a.target_node_id, a.uncertain, a.confidence) == (
            b.source_node_id, b.target_node_id, b.uncertain, b.confidence)
    assert json.load(open(out))["class_name"] == "PoseGraph"


def test_pose_graph_file_errors(tmp_path):
    with pytest.raises(o3d.O3DFileNotFoundError):
        o3d.io.read_pose_graph(str(tmp_path / "missing.json"))
    bad = tmp_path / "bad.json"
    bad.write_text('{"class_name": "PoseGraph", "nodes": [{"pose": [1, 2]}]}')
    with pytest.raises(o3d.ParseError):
        o3d.io.read_pose_graph(str(bad))


# ---- global optimization

def test_global_optimization_prunes_a_false_loop_closure():
    graph, truth = make_loop_graph()
    summary = reg.global_optimization(graph, reg.GlobalOptimizationLevenbergMarquardt(),
                                      reg.GlobalOptimizationConvergenceCriteria(), OPTION)
    # record_python_registration.py: posegraph.edges_after, posegraph.kept_pairs, posegraph.poses_fp
    assert len(graph.edges) == 6
    assert [(e.source_node_id, e.target_node_id) for e in graph.edges] == [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (5, 0)]
    assert summary.pruned_edges == 1 and summary.final_residual < summary.initial_residual
    poses = np.array([n.pose for n in graph.nodes])
    np.testing.assert_allclose(poses, np.array(truth), atol=1e-6)  # the exact edges pin the truth (node 0 fixed)
    assert fp(poses) == pytest.approx(389.7231679351946, abs=1e-4)
    assert graph.edges[5].confidence > 0.9


def test_gauss_newton_and_optimize_pose_graph_method():
    graph, truth = make_loop_graph()
    reg.global_optimization(graph, reg.GlobalOptimizationGaussNewton(), reg.GlobalOptimizationConvergenceCriteria(),
                            OPTION)
    np.testing.assert_allclose(np.array([n.pose for n in graph.nodes]), np.array(truth), atol=1e-5)
    other, _ = make_loop_graph()
    reg.GlobalOptimizationLevenbergMarquardt().OptimizePoseGraph(other, reg.GlobalOptimizationConvergenceCriteria(),
                                                                OPTION)
    assert len(other.edges) == 6


def test_global_optimization_progress_cancel_and_errors(capsys):
    graph, _ = make_loop_graph()
    before = np.array([n.pose for n in graph.nodes])
    calls = []
    with pytest.raises(o3d.CancelledError):
        reg.global_optimization(graph, reg.GlobalOptimizationLevenbergMarquardt(),
                                reg.GlobalOptimizationConvergenceCriteria(), OPTION,
                                callback=lambda f: calls.append(f) or True)
    assert len(calls) == 1
    np.testing.assert_array_equal(np.array([n.pose for n in graph.nodes]), before)  # unchanged
    assert len(graph.edges) == 7
    seen = []
    reg.global_optimization(graph, option=OPTION, callback=seen.append, print_progress=True, num_threads=2)
    assert seen and all(0.0 <= f <= 1.0 for f in seen)
    assert "Global optimization" in capsys.readouterr().err

    broken, _ = make_loop_graph()
    broken.edges.append(reg.PoseGraphEdge(0, 17))  # names a missing node
    with pytest.raises(o3d.InvalidArgumentError):
        reg.global_optimization(broken, option=OPTION)
    assert len(broken.edges) == 8
    with pytest.raises(ValueError):
        reg.global_optimization(broken, "LM")
    with pytest.raises(ValueError):
        reg.global_optimization(broken, option=reg.GlobalOptimizationConvergenceCriteria())
    with pytest.raises(TypeError):
        reg.global_optimization("graph")
