//! `PoseGraph` (o3d.pipelines.registration.PoseGraph) for multiway registration: nodes (poses),
//! edges (relative transformations with information matrices), Open3D's JSON files, and global
//! optimization (Gauss-Newton or Levenberg-Marquardt with the line process that prunes false loop
//! closures, Choi et al. 2015). Matrices are row-major (`m[row][col]`); an edge (s, t, T) says
//! that T maps points of node s's frame into node t's: `pose_t^-1 * pose_s ~ T`.
use std::fmt;
use std::mem::size_of;
use std::path::Path;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::io::c_path;
use crate::progress::progress_pair;
use crate::util::{c_enum, handle, mat4_ptr, options};

include!("generated/posegraph.rs");

impl PoseGraphEdge {
    /// Open3D's `PoseGraphEdge(source, target, transformation, information, uncertain)`, with the
    /// default confidence (1).
    pub fn new(
        source_node_id: i32,
        target_node_id: i32,
        transformation: [[f64; 4]; 4],
        information: [[f64; 6]; 6],
        uncertain: bool,
    ) -> PoseGraphEdge {
        PoseGraphEdge { source_node_id, target_node_id, transformation, information, uncertain, ..Default::default() }
    }
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
        let mut raw = PoseGraphEdge::raw_default()?;
        // SAFETY: valid handle; raw is an initialised edge with struct_size set.
        check(unsafe { sys::o3d_pose_graph_get_edge(&mut raw, self.as_raw(), index) })?;
        PoseGraphEdge::from_raw(&raw)
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


impl Default for GlobalOptimizationMethod {
    /// The library's default (`o3d_global_optimization_options_init`: Levenberg-Marquardt).
    fn default() -> Self {
        GlobalOptimizationOptions::default().method
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

progress_pair! {
    /// Optimize the node poses of `graph` in place (Open3D's global_optimization): optimize with the
    /// line process, remove uncertain edges whose confidence fell below `edge_prune_threshold`,
    /// optimize again; edge confidences are updated. An edge naming a missing node is an error and
    /// leaves `graph` unchanged.
    pub fn global_optimization;
    /// As [`global_optimization`], reporting the share of `max_iteration` done over both passes to
    /// `progress` on this thread. `ControlFlow::Break(())` stops with [`crate::ErrorCode::Cancelled`] and
    /// leaves `graph` unchanged; a panic in `progress` cancels and resumes after the call.
    pub fn global_optimization_with_progress(
        graph: &mut PoseGraph,
        options: &GlobalOptimizationOptions,
    ) -> Result<GlobalOptimizationSummary>;
    |callback, user_data| {
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        let mut raw = sys::o3d_global_optimization_summary_t {
            struct_size: size_of::<sys::o3d_global_optimization_summary_t>() as u32,
            ..Default::default()
        };
        // SAFETY: valid handle held exclusively, options from init, summary with struct_size set.
        check(unsafe { sys::o3d_global_optimization(&mut raw, graph.raw.as_ptr(), &opts) })?;
        Ok(GlobalOptimizationSummary {
            iterations: raw.iterations.max(0) as usize,
            initial_residual: raw.initial_residual,
            final_residual: raw.final_residual,
            pruned_edges: raw.pruned_edges.max(0) as usize,
        })
    }
}
