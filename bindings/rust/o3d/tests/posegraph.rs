//! PoseGraph: nodes and edges, JSON files, global optimization pruning a false loop closure,
//! progress and cancellation, bad arguments.
mod common;

use std::ops::ControlFlow;

use common::*;
use o3d::registration::{
    self, GlobalOptimizationMethod, GlobalOptimizationOptions, PoseGraph, PoseGraphEdge, IDENTITY,
};
use o3d::{io, ErrorCode};

fn translation(t: [f64; 3]) -> [[f64; 4]; 4] {
    rigid([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], t)
}

fn scaled_identity6(s: f64) -> [[f64; 6]; 6] {
    let mut m = [[0.0; 6]; 6];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = s;
    }
    m
}

/// The edge (s, t) that `poses` satisfy exactly: pose_t^-1 * pose_s.
fn exact_edge(poses: &[[[f64; 4]; 4]], s: usize, t: usize, uncertain: bool) -> PoseGraphEdge {
    let transformation = mat_mul(&rigid_inverse(&poses[t]), &poses[s]);
    PoseGraphEdge::new(s as i32, t as i32, transformation, scaled_identity6(1000.0), uncertain)
}

#[test]
fn nodes_and_edges_can_be_added_read_replaced_and_cleared() {
    let mut g = PoseGraph::new().unwrap();
    assert_eq!((g.num_nodes(), g.num_edges()), (0, 0));
    let pose = rigid(rotation([0.0, 0.0, 1.0], 0.3), [1.0, 2.0, 3.0]);
    g.add_node(&IDENTITY).unwrap();
    g.add_node(&pose).unwrap();
    assert_eq!(g.node(1).unwrap(), pose);
    assert_eq!(g.nodes().unwrap(), vec![IDENTITY, pose]);
    g.set_node(0, &pose).unwrap();
    assert_eq!(g.node(0).unwrap(), pose);

    let edge = PoseGraphEdge { confidence: 0.5, ..PoseGraphEdge::new(0, 1, pose, scaled_identity6(2.0), true) };
    g.add_edge(&edge).unwrap();
    assert_eq!(g.edge(0).unwrap(), edge);
    let replaced = PoseGraphEdge { target_node_id: 0, uncertain: false, ..edge };
    g.set_edge(0, &replaced).unwrap();
    assert_eq!(g.edges().unwrap(), vec![replaced]);

    // Clones are deep.
    let copy = g.clone();
    g.clear().unwrap();
    assert_eq!((g.num_nodes(), g.num_edges()), (0, 0));
    assert_eq!((copy.num_nodes(), copy.num_edges()), (2, 1));
    assert_eq!(copy.edge(0).unwrap(), replaced);

    assert_eq!(PoseGraphEdge::library_defaults().unwrap(), PoseGraphEdge::default());
    assert_eq!(GlobalOptimizationOptions::library_defaults().unwrap(), GlobalOptimizationOptions::default());
}

#[test]
fn bad_indices_and_poses_are_errors() {
    let mut g = PoseGraph::new().unwrap();
    g.add_node(&IDENTITY).unwrap();
    assert_eq!(g.node(1).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(g.set_node(5, &IDENTITY).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(g.edge(0).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(g.set_edge(0, &PoseGraphEdge::default()).unwrap_err().code, ErrorCode::InvalidArgument);
    let mut not_rigid = IDENTITY;
    not_rigid[0][0] = 2.0;
    assert_eq!(g.add_node(&not_rigid).unwrap_err().code, ErrorCode::InvalidArgument);
    let mut nan = IDENTITY;
    nan[1][3] = f64::NAN;
    assert_eq!(g.set_node(0, &nan).unwrap_err().code, ErrorCode::InvalidArgument);
    let bad_edge = PoseGraphEdge { confidence: f64::NAN, ..Default::default() };
    assert_eq!(g.add_edge(&bad_edge).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(g.num_nodes(), 1, "failed calls leave the graph as it was");
}

#[test]
fn json_round_trip_of_the_shared_pose_graph() {
    let Some(path) = data_file("open3d/test_pose_graph.json") else { return };
    let g = io::read_pose_graph(&path).unwrap();
    assert_eq!((g.num_nodes(), g.num_edges()), (2, 2));
    // The file stores matrices column by column: its first "information" values are row 0's
    // first column (Open3D's JSON layout).
    let first = g.edge(0).unwrap();
    assert!((first.information[0][0] - -0.098_422_193_060_090_92).abs() < 1e-15);
    assert!((first.information[1][0] - -0.295_754_875_331_888_8).abs() < 1e-15);

    let dir = TempDir::new("posegraph");
    let out = dir.path("graph.json");
    io::write_pose_graph(&out, &g).unwrap();
    let back = io::read_pose_graph(&out).unwrap();
    assert_eq!(back.nodes().unwrap(), g.nodes().unwrap());
    assert_eq!(back.edges().unwrap(), g.edges().unwrap());

    assert_eq!(io::read_pose_graph(dir.path("missing.json")).unwrap_err().code, ErrorCode::Io);
    std::fs::write(dir.path("bad.json"), "{\"class_name\": \"PoseGraph\", \"nodes\": [").unwrap();
    assert_eq!(io::read_pose_graph(dir.path("bad.json")).unwrap_err().code, ErrorCode::Parse);
}

/// Six poses along a gentle curve, odometry between neighbours, a true loop closure 0 -> 5 and a
/// false one 1 -> 4 (off by a metre); the starting poses are the truth slightly disturbed.
fn graph_with_a_false_loop_closure() -> (PoseGraph, Vec<[[f64; 4]; 4]>) {
    let truth: Vec<[[f64; 4]; 4]> = (0..6)
        .map(|i| {
            let i = i as f64;
            rigid(rotation([0.0, 0.0, 1.0], 0.1 * i), [i, 0.2 * i * i, 0.05 * i])
        })
        .collect();
    let mut g = PoseGraph::new().unwrap();
    for (i, pose) in truth.iter().enumerate() {
        let noise = rigid(rotation([1.0, 1.0, 0.0], 0.002 * i as f64), [0.01 * i as f64, -0.005 * i as f64, 0.0]);
        g.add_node(&mat_mul(pose, &noise)).unwrap();
    }
    for i in 0..5 {
        g.add_edge(&exact_edge(&truth, i, i + 1, false)).unwrap();
    }
    g.add_edge(&exact_edge(&truth, 0, 5, true)).unwrap();
    let mut wrong = exact_edge(&truth, 1, 4, true);
    wrong.transformation = mat_mul(&translation([1.0, -0.5, 0.3]), &wrong.transformation);
    g.add_edge(&wrong).unwrap();
    (g, truth)
}

fn max_pose_error(g: &PoseGraph, truth: &[[[f64; 4]; 4]]) -> f64 {
    // Poses are fixed up to the reference node (node 0, which starts at the truth).
    g.nodes().unwrap().iter().zip(truth).map(|(a, b)| max_abs_diff(a, b)).fold(0.0, f64::max)
}

#[test]
fn global_optimization_prunes_the_false_loop_closure() {
    for method in [GlobalOptimizationMethod::LevenbergMarquardt, GlobalOptimizationMethod::GaussNewton] {
        let (mut g, truth) = graph_with_a_false_loop_closure();
        let before = max_pose_error(&g, &truth);
        let opts = GlobalOptimizationOptions { method, ..Default::default() };
        let summary = registration::global_optimization(&mut g, &opts).unwrap();
        assert_eq!(summary.pruned_edges, 1, "{method:?}: {summary:?}");
        assert!(summary.iterations > 0);
        assert!(summary.final_residual < summary.initial_residual, "{summary:?}");
        // The false 1 -> 4 edge is gone, the true loop closure stays with full confidence.
        let edges = g.edges().unwrap();
        assert_eq!(edges.len(), 6);
        assert!(!edges.iter().any(|e| (e.source_node_id, e.target_node_id) == (1, 4)));
        let kept = edges.iter().find(|e| (e.source_node_id, e.target_node_id) == (0, 5)).unwrap();
        assert!(kept.uncertain && kept.confidence > 0.9, "{kept:?}");
        let after = max_pose_error(&g, &truth);
        assert!(after < 1e-4 && after < before, "{method:?}: {before} -> {after}");
    }
}

#[test]
fn global_optimization_reports_progress_and_can_be_cancelled() {
    let (mut g, _) = graph_with_a_false_loop_closure();
    let before = g.nodes().unwrap();
    let mut calls = 0;
    let err = registration::global_optimization_with_progress(&mut g, &Default::default(), |_| {
        calls += 1;
        ControlFlow::Break(())
    })
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");
    assert_eq!(calls, 1);
    assert_eq!(g.nodes().unwrap(), before, "cancelling leaves the graph unchanged");
    assert_eq!(g.num_edges(), 7);

    let mut seen = Vec::new();
    registration::global_optimization_with_progress(&mut g, &Default::default(), |f| {
        seen.push(f);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert!(!seen.is_empty() && seen.iter().all(|f| (0.0..=1.0).contains(f)), "{seen:?}");
    assert!(seen.windows(2).all(|w| w[0] <= w[1]), "{seen:?}");
}

#[test]
fn global_optimization_rejects_bad_graphs_and_options() {
    let (mut g, _) = graph_with_a_false_loop_closure();
    let before = g.nodes().unwrap();
    g.add_edge(&PoseGraphEdge::new(2, 9, IDENTITY, scaled_identity6(1.0), false)).unwrap();
    let err = registration::global_optimization(&mut g, &Default::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    assert_eq!(g.nodes().unwrap(), before);
    assert_eq!(g.num_edges(), 8);

    let (mut g, _) = graph_with_a_false_loop_closure();
    for opts in [
        GlobalOptimizationOptions { reference_node: Some(6), ..Default::default() },
        GlobalOptimizationOptions { max_correspondence_distance: f64::NAN, ..Default::default() },
        GlobalOptimizationOptions { edge_prune_threshold: -0.5, ..Default::default() },
    ] {
        let err = registration::global_optimization(&mut g, &opts).unwrap_err();
        assert_eq!(err.code, ErrorCode::InvalidArgument, "{opts:?}: {err}");
    }
    // A fixed reference node other than the first works too.
    let summary = registration::global_optimization(
        &mut g,
        &GlobalOptimizationOptions { reference_node: Some(2), ..Default::default() },
    )
    .unwrap();
    assert_eq!(summary.pruned_edges, 1);
}
