//! `PoseGraph` (o3d.pipelines.registration.PoseGraph) for multiway registration: nodes (poses),
//! edges (relative transformations with information matrices), Open3D's JSON files, and global
//! optimization (Gauss-Newton or Levenberg-Marquardt with the line process that prunes false loop
//! closures, Choi et al. 2015). Matrices are row-major (`m[row][col]`); an edge (s, t, T) says
//! that T maps points of node s's frame into node t's: `pose_t^-1 * pose_s ~ T`.
use std::fmt;
use std::mem::size_of;
use std::ops::ControlFlow;
use std::path::Path;

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::io::c_path;
use crate::progress::with_progress;
use crate::registration::IDENTITY;
use crate::util::{handle, init_struct, mat4_ptr, to_i32};

/// The 6x6 identity.
const IDENTITY6: [[f64; 6]; 6] = {
    let mut m = [[0.0; 6]; 6];
    let mut i = 0;
    while i < 6 {
        m[i][i] = 1.0;
        i += 1;
    }
    m
};

/// A pose-graph edge (o3d.pipelines.registration.PoseGraphEdge). `Default` is Open3D's: nodes
/// 0 -> 0, identity transformation and information, certain (odometry), confidence 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseGraphEdge {
    /// Index of the source node.
    pub source_node_id: i32,
    /// Index of the target node.
    pub target_node_id: i32,
    /// Maps points of the source node's frame into the target node's.
    pub transformation: [[f64; 4]; 4],
    /// 6x6 information matrix (rotation first, then translation, as Open3D).
    pub information: [[f64; 6]; 6],
    /// A loop closure the line process may prune (false: odometry).
    pub uncertain: bool,
    /// Line-process weight in [0, 1].
    pub confidence: f64,
}

impl Default for PoseGraphEdge {
    fn default() -> Self {
        PoseGraphEdge {
            source_node_id: 0,
            target_node_id: 0,
            transformation: IDENTITY,
            information: IDENTITY6,
            uncertain: false,
            confidence: 1.0,
        }
    }
}

impl PoseGraphEdge {
    /// Open3D's `PoseGraphEdge(source, target, transformation, information, uncertain)`, confidence 1.
    pub fn new(
        source_node_id: i32,
        target_node_id: i32,
        transformation: [[f64; 4]; 4],
        information: [[f64; 6]; 6],
        uncertain: bool,
    ) -> PoseGraphEdge {
        PoseGraphEdge { source_node_id, target_node_id, transformation, information, uncertain, confidence: 1.0 }
    }

    /// The library's default edge (`o3d_pose_graph_edge_init`); equal to `Default` for a matching library.
    pub fn library_default() -> Result<PoseGraphEdge> {
        Ok(PoseGraphEdge::from_raw(&raw_edge()?))
    }

    fn from_raw(raw: &sys::o3d_pose_graph_edge_t) -> PoseGraphEdge {
        let mut e = PoseGraphEdge {
            source_node_id: raw.source_node_id,
            target_node_id: raw.target_node_id,
            uncertain: raw.uncertain != 0,
            confidence: raw.confidence,
            ..PoseGraphEdge::default()
        };
        for r in 0..4 {
            e.transformation[r].copy_from_slice(&raw.transformation[4 * r..4 * r + 4]);
        }
        for r in 0..6 {
            e.information[r].copy_from_slice(&raw.information[6 * r..6 * r + 6]);
        }
        e
    }

    fn to_raw(self) -> Result<sys::o3d_pose_graph_edge_t> {
        let mut raw = raw_edge()?;
        raw.source_node_id = self.source_node_id;
        raw.target_node_id = self.target_node_id;
        for r in 0..4 {
            raw.transformation[4 * r..4 * r + 4].copy_from_slice(&self.transformation[r]);
        }
        for r in 0..6 {
            raw.information[6 * r..6 * r + 6].copy_from_slice(&self.information[r]);
        }
        raw.uncertain = self.uncertain as i32;
        raw.confidence = self.confidence;
        Ok(raw)
    }
}

fn raw_edge() -> Result<sys::o3d_pose_graph_edge_t> {
    // SAFETY: o3d_pose_graph_edge_t is plain numbers and nullable pointers; o3d_pose_graph_edge_init is its init.
    unsafe { init_struct(|p, n| sys::o3d_pose_graph_edge_init(p, n)) }
}

handle! {
    /// A pose graph: one pose per node (row-major 4x4, a rigid transform) and the edges between them.
    ///
    /// Owns an `o3d_pose_graph_t`. `Send` and `Sync`: `&self` methods only read, every mutation
    /// (including [`global_optimization`]) takes `&mut self`.
    PoseGraph(sys::o3d_pose_graph_t, "pose graph"), new_pose_graph, sys::o3d_pose_graph_destroy, sys::o3d_pose_graph_clone
}

impl PoseGraph {
    /// An empty graph.
    pub fn new() -> Result<PoseGraph> {
        // SAFETY: out-pointer provided by adopt.
        new_pose_graph(|out| unsafe { sys::o3d_pose_graph_create(out) })
    }

    /// Number of nodes.
    pub fn num_nodes(&self) -> usize {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer (the call fails only for NULL).
        let status = unsafe { sys::o3d_pose_graph_num_nodes(&mut n, self.as_raw()) };
        check(status).unwrap_or_else(|e| panic!("o3d_pose_graph_num_nodes failed: {e}"));
        n
    }

    /// Number of edges.
    pub fn num_edges(&self) -> usize {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer (the call fails only for NULL).
        let status = unsafe { sys::o3d_pose_graph_num_edges(&mut n, self.as_raw()) };
        check(status).unwrap_or_else(|e| panic!("o3d_pose_graph_num_edges failed: {e}"));
        n
    }

    /// Append a node with `pose` (a finite rigid transform; else an error).
    pub fn add_node(&mut self, pose: &[[f64; 4]; 4]) -> Result<()> {
        // SAFETY: valid handle, 16 doubles.
        check(unsafe { sys::o3d_pose_graph_add_node(self.raw.as_ptr(), mat4_ptr(pose)) })
    }

    /// The pose of node `index` (out of range: an error).
    pub fn node(&self, index: usize) -> Result<[[f64; 4]; 4]> {
        let mut pose = [[0.0; 4]; 4];
        // SAFETY: valid handle, room for 16 doubles.
        check(unsafe { sys::o3d_pose_graph_get_node(pose.as_mut_ptr().cast(), self.as_raw(), index) })?;
        Ok(pose)
    }

    /// Replace the pose of node `index`.
    pub fn set_node(&mut self, index: usize, pose: &[[f64; 4]; 4]) -> Result<()> {
        // SAFETY: valid handle, 16 doubles.
        check(unsafe { sys::o3d_pose_graph_set_node(self.raw.as_ptr(), index, mat4_ptr(pose)) })
    }

    /// Every node pose, in order.
    pub fn nodes(&self) -> Result<Vec<[[f64; 4]; 4]>> {
        (0..self.num_nodes()).map(|i| self.node(i)).collect()
    }

    /// Append an edge. Node ids are checked by [`global_optimization`], not here (Open3D builds
    /// edges first).
    pub fn add_edge(&mut self, edge: &PoseGraphEdge) -> Result<()> {
        let raw = edge.to_raw()?;
        // SAFETY: valid handle and edge struct.
        check(unsafe { sys::o3d_pose_graph_add_edge(self.raw.as_ptr(), &raw) })
    }

    /// Edge `index` (out of range: an error).
    pub fn edge(&self, index: usize) -> Result<PoseGraphEdge> {
        let mut raw = raw_edge()?;
        // SAFETY: valid handle; raw is an initialised edge with struct_size set.
        check(unsafe { sys::o3d_pose_graph_get_edge(&mut raw, self.as_raw(), index) })?;
        Ok(PoseGraphEdge::from_raw(&raw))
    }

    /// Replace edge `index`.
    pub fn set_edge(&mut self, index: usize, edge: &PoseGraphEdge) -> Result<()> {
        let raw = edge.to_raw()?;
        // SAFETY: valid handle and edge struct.
        check(unsafe { sys::o3d_pose_graph_set_edge(self.raw.as_ptr(), index, &raw) })
    }

    /// Every edge, in order.
    pub fn edges(&self) -> Result<Vec<PoseGraphEdge>> {
        (0..self.num_edges()).map(|i| self.edge(i)).collect()
    }

    /// Remove every node and edge.
    pub fn clear(&mut self) -> Result<()> {
        // SAFETY: valid handle.
        check(unsafe { sys::o3d_pose_graph_clear(self.raw.as_ptr()) })
    }
}

impl fmt::Debug for PoseGraph {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("PoseGraph").field("num_nodes", &self.num_nodes()).field("num_edges", &self.num_edges()).finish()
    }
}

/// Read Open3D's JSON pose graph. @see o3d.io.read_pose_graph
pub fn read_pose_graph(path: impl AsRef<Path>) -> Result<PoseGraph> {
    let path = c_path(path.as_ref())?;
    // SAFETY: NUL-terminated path.
    new_pose_graph(|out| unsafe { sys::o3d_io_read_pose_graph(out, path.as_ptr()) })
}

/// Write `graph` in Open3D's JSON layout. @see o3d.io.write_pose_graph
pub fn write_pose_graph(path: impl AsRef<Path>, graph: &PoseGraph) -> Result<()> {
    let path = c_path(path.as_ref())?;
    // SAFETY: NUL-terminated path, valid handle.
    check(unsafe { sys::o3d_io_write_pose_graph(path.as_ptr(), graph.as_raw()) })
}

/// Solver of [`global_optimization`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GlobalOptimizationMethod {
    /// GlobalOptimizationGaussNewton.
    GaussNewton,
    /// GlobalOptimizationLevenbergMarquardt (default).
    #[default]
    LevenbergMarquardt,
}

/// GlobalOptimizationConvergenceCriteria + GlobalOptimizationOption + method and threads.
/// `Default` is Open3D's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GlobalOptimizationOptions {
    /// Solver (default Levenberg-Marquardt).
    pub method: GlobalOptimizationMethod,
    /// Iterations per pass (default 100).
    pub max_iteration: usize,
    /// Default 1e-6.
    pub min_relative_increment: f64,
    /// Default 1e-6.
    pub min_relative_residual_increment: f64,
    /// Default 1e-6.
    pub min_right_term: f64,
    /// Default 1e-6.
    pub min_residual: f64,
    /// Levenberg-Marquardt damping retries per iteration (default 20).
    pub max_iteration_lm: usize,
    /// Levenberg-Marquardt (default 2/3).
    pub upper_scale_factor: f64,
    /// Levenberg-Marquardt (default 1/3).
    pub lower_scale_factor: f64,
    /// Sets the line-process scale (default 0.075).
    pub max_correspondence_distance: f64,
    /// Uncertain edges whose confidence ends below it are removed (default 0.25).
    pub edge_prune_threshold: f64,
    /// Weight of loop closures against odometry (default 1.0).
    pub preference_loop_closure: f64,
    /// The node kept fixed; `None` (default): the first.
    pub reference_node: Option<usize>,
    /// Threads; 0 = the library default (default 0). The result does not depend on it.
    pub num_threads: usize,
}

impl Default for GlobalOptimizationOptions {
    fn default() -> Self {
        GlobalOptimizationOptions {
            method: GlobalOptimizationMethod::LevenbergMarquardt,
            max_iteration: 100,
            min_relative_increment: 1e-6,
            min_relative_residual_increment: 1e-6,
            min_right_term: 1e-6,
            min_residual: 1e-6,
            max_iteration_lm: 20,
            upper_scale_factor: 2.0 / 3.0,
            lower_scale_factor: 1.0 / 3.0,
            max_correspondence_distance: 0.075,
            edge_prune_threshold: 0.25,
            preference_loop_closure: 1.0,
            reference_node: None,
            num_threads: 0,
        }
    }
}

fn raw_global_options() -> Result<sys::o3d_global_optimization_options_t> {
    // SAFETY: o3d_global_optimization_options_t is plain numbers and nullable pointers; o3d_global_optimization_options_init is its init.
    unsafe { init_struct(|p, n| sys::o3d_global_optimization_options_init(p, n)) }
}

impl GlobalOptimizationOptions {
    /// The library's defaults (`o3d_global_optimization_options_init`); equal to `Default` for a
    /// matching library.
    pub fn library_defaults() -> Result<GlobalOptimizationOptions> {
        let raw = raw_global_options()?;
        let method = match raw.method {
            sys::O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON => GlobalOptimizationMethod::GaussNewton,
            sys::O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT => GlobalOptimizationMethod::LevenbergMarquardt,
            other => return Err(Error::new(ErrorCode::Internal, format!("unknown optimization method {other}"))),
        };
        Ok(GlobalOptimizationOptions {
            method,
            max_iteration: raw.max_iteration.max(0) as usize,
            min_relative_increment: raw.min_relative_increment,
            min_relative_residual_increment: raw.min_relative_residual_increment,
            min_right_term: raw.min_right_term,
            min_residual: raw.min_residual,
            max_iteration_lm: raw.max_iteration_lm.max(0) as usize,
            upper_scale_factor: raw.upper_scale_factor,
            lower_scale_factor: raw.lower_scale_factor,
            max_correspondence_distance: raw.max_correspondence_distance,
            edge_prune_threshold: raw.edge_prune_threshold,
            preference_loop_closure: raw.preference_loop_closure,
            reference_node: usize::try_from(raw.reference_node).ok(),
            num_threads: raw.num_threads.max(0) as usize,
        })
    }

    fn to_raw(self) -> Result<sys::o3d_global_optimization_options_t> {
        let mut raw = raw_global_options()?;
        raw.method = match self.method {
            GlobalOptimizationMethod::GaussNewton => sys::O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON,
            GlobalOptimizationMethod::LevenbergMarquardt => sys::O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT,
        };
        raw.max_iteration = to_i32(self.max_iteration, "max_iteration")?;
        raw.min_relative_increment = self.min_relative_increment;
        raw.min_relative_residual_increment = self.min_relative_residual_increment;
        raw.min_right_term = self.min_right_term;
        raw.min_residual = self.min_residual;
        raw.max_iteration_lm = to_i32(self.max_iteration_lm, "max_iteration_lm")?;
        raw.upper_scale_factor = self.upper_scale_factor;
        raw.lower_scale_factor = self.lower_scale_factor;
        raw.max_correspondence_distance = self.max_correspondence_distance;
        raw.edge_prune_threshold = self.edge_prune_threshold;
        raw.preference_loop_closure = self.preference_loop_closure;
        raw.reference_node = match self.reference_node {
            Some(node) => to_i32(node, "reference_node")?,
            None => -1,
        };
        raw.num_threads = to_i32(self.num_threads, "num_threads")?;
        Ok(raw)
    }
}

/// What a global optimization did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct GlobalOptimizationSummary {
    /// Iterations of both passes.
    pub iterations: usize,
    /// The robust objective before the first pass.
    pub initial_residual: f64,
    /// The robust objective after the last pass.
    pub final_residual: f64,
    /// Uncertain edges removed for a confidence below `edge_prune_threshold`.
    pub pruned_edges: usize,
}

/// Optimize the node poses of `graph` in place (Open3D's global_optimization): optimize with the
/// line process, remove uncertain edges whose confidence fell below `edge_prune_threshold`,
/// optimize again; edge confidences are updated. An edge naming a missing node is an error and
/// leaves `graph` unchanged.
pub fn global_optimization(
    graph: &mut PoseGraph,
    options: &GlobalOptimizationOptions,
) -> Result<GlobalOptimizationSummary> {
    let opts = options.to_raw()?;
    optimize(graph, &opts)
}

/// As [`global_optimization`], reporting the share of `max_iteration` done over both passes to
/// `progress` on this thread. `ControlFlow::Break(())` stops with [`ErrorCode::Cancelled`] and
/// leaves `graph` unchanged; a panic in `progress` cancels and resumes after the call.
pub fn global_optimization_with_progress<F>(
    graph: &mut PoseGraph,
    options: &GlobalOptimizationOptions,
    progress: F,
) -> Result<GlobalOptimizationSummary>
where
    F: FnMut(f64) -> ControlFlow<()>,
{
    let mut opts = options.to_raw()?;
    with_progress(progress, |callback, user_data| {
        (opts.progress, opts.user_data) = (callback, user_data);
        optimize(graph, &opts)
    })
}

fn optimize(graph: &mut PoseGraph, opts: &sys::o3d_global_optimization_options_t) -> Result<GlobalOptimizationSummary> {
    let mut raw = sys::o3d_global_optimization_summary_t {
        struct_size: size_of::<sys::o3d_global_optimization_summary_t>() as u32,
        ..Default::default()
    };
    // SAFETY: valid handle held exclusively, options from init, summary with struct_size set.
    check(unsafe { sys::o3d_global_optimization(&mut raw, graph.raw.as_ptr(), opts) })?;
    Ok(GlobalOptimizationSummary {
        iterations: raw.iterations.max(0) as usize,
        initial_residual: raw.initial_residual,
        final_residual: raw.final_residual,
        pruned_edges: raw.pruned_edges.max(0) as usize,
    })
}
