//! `Octree` (o3d.geometry.Octree with point-and-color leaves) over a point cloud or a voxel grid.
use std::fmt;
use std::ptr;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::pointcloud::PointCloud;
use crate::util::handle;
use crate::voxelgrid::VoxelGrid;

include!("generated/octree.rs");

/// Where a node sits (o3d.geometry.OctreeNodeInfo).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct OctreeNodeInfo {
    /// The node cube's min corner.
    pub origin: [f64; 3],
    /// The node cube's edge.
    pub size: f64,
    /// 0 for the root.
    pub depth: i32,
    /// 0..7 within its parent (0 for the root).
    pub child_index: i32,
}

impl OctreeNodeInfo {
    fn from_raw(raw: sys::o3d_octree_node_info_t) -> OctreeNodeInfo {
        OctreeNodeInfo { origin: raw.origin, size: raw.size, depth: raw.depth, child_index: raw.child_index }
    }
}

/// A leaf found by [`Octree::locate_leaf_node`]: where it is, the mean color of its points and
/// their indices (ascending).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct OctreeLeaf {
    /// The leaf's position in the tree.
    pub info: OctreeNodeInfo,
    /// Mean color of the leaf's points.
    pub color: [f64; 3],
    /// Indices of the leaf's points in the cloud the tree was built from.
    pub indices: Vec<i32>,
}

handle! {
    /// An octree: a cube of edge `size` at `origin`, split down to `max_depth`.
    ///
    /// Owns an `o3d_octree_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and
    /// rebuilding takes `&mut self`.
    Octree(sys::o3d_octree_t, "octree"), new_octree, sys::o3d_octree_destroy
}

impl Octree {
    /// Whether `point` lies in the half-open cube `[origin, origin + size)^3` (Open3D's static
    /// `Octree.is_point_in_bound`).
    pub fn is_point_in_bound(point: [f64; 3], origin: [f64; 3], size: f64) -> Result<bool> {
        let mut out = 0i32;
        // SAFETY: one int out; 3 + 3 doubles in.
        check(unsafe { sys::o3d_octree_is_point_in_bound(&mut out, point.as_ptr(), origin.as_ptr(), size) })?;
        Ok(out != 0)
    }

    /// The voxel grid of the leaves (Open3D's `to_voxel_grid`): voxel size = size / 2^max_depth, origin at
    /// the octree's origin, one voxel per leaf with its color.
    pub fn to_voxel_grid(&self) -> Result<VoxelGrid> {
        VoxelGrid::create_from_octree(self)
    }

    /// The root cube's min corner.
    pub fn origin(&self) -> Result<[f64; 3]> {
        let mut v = [0.0; 3];
        // SAFETY: room for 3 doubles; the other outputs are skipped.
        check(unsafe { sys::o3d_octree_get_root(v.as_mut_ptr(), ptr::null_mut(), ptr::null_mut(), self.as_raw()) })?;
        Ok(v)
    }

    /// The root cube's edge.
    pub fn size(&self) -> Result<f64> {
        let mut v = 0.0;
        // SAFETY: one double; the other outputs are skipped.
        check(unsafe { sys::o3d_octree_get_root(ptr::null_mut(), &mut v, ptr::null_mut(), self.as_raw()) })?;
        Ok(v)
    }

    /// The depth of the leaves.
    pub fn max_depth(&self) -> Result<usize> {
        let mut v = 0i32;
        // SAFETY: one int; the other outputs are skipped.
        check(unsafe { sys::o3d_octree_get_root(ptr::null_mut(), ptr::null_mut(), &mut v, self.as_raw()) })?;
        Ok(v.max(0) as usize)
    }

    /// The leaf containing `point`; `None` when the point is outside the root or in an empty cell.
    pub fn locate_leaf_node(&self, point: [f64; 3]) -> Result<Option<OctreeLeaf>> {
        let locate = |indices: &mut [i32], info: &mut sys::o3d_octree_node_info_t, color: &mut [f64; 3]| {
            let (mut found, mut n) = (0i32, 0usize);
            let out = if indices.is_empty() { ptr::null_mut() } else { indices.as_mut_ptr() };
            // SAFETY: 3 doubles in; writable struct and 3 doubles out; `out` has room for
            // indices.len() ints or is NULL.
            check(unsafe {
                sys::o3d_octree_locate_leaf_node(
                    &mut found,
                    info,
                    color.as_mut_ptr(),
                    out,
                    indices.len(),
                    &mut n,
                    self.as_raw(),
                    point.as_ptr(),
                )
            })?;
            Ok::<_, crate::Error>((found != 0, n))
        };
        let mut info = sys::o3d_octree_node_info_t::default();
        let mut color = [0.0; 3];
        let (found, n) = locate(&mut [], &mut info, &mut color)?;
        if !found {
            return Ok(None);
        }
        let mut indices = vec![0i32; n];
        let (_, written) = locate(&mut indices, &mut info, &mut color)?;
        indices.truncate(written.min(n));
        Ok(Some(OctreeLeaf { info: OctreeNodeInfo::from_raw(info), color, indices }))
    }
}

impl fmt::Debug for Octree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Octree")
            .field("max_depth", &self.max_depth().unwrap_or(0))
            .field("leaves", &self.num_leaf_nodes().unwrap_or(0))
            .finish()
    }
}
