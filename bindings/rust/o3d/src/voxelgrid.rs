//! `VoxelGrid` (o3d.geometry.VoxelGrid): the occupied cells of a regular grid, each with a color.
use std::fmt;

use o3d_sys as sys;

use crate::array::{cols, has};
use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::{copy_out, handle};

include!("generated/voxelgrid.rs");

/// One occupied cell (o3d.geometry.Voxel).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Voxel {
    /// Integer cell coordinates; cell (0,0,0) starts at the grid's origin.
    pub grid_index: [i32; 3],
    /// Mean color of what fell in the cell (0 without colors).
    pub color: [f64; 3],
}

handle! {
    /// A sparse voxel grid of cubes of edge `voxel_size` starting at `origin`.
    ///
    /// Owns an `o3d_voxelgrid_t`; immutable once built, so `Send` and `Sync`.
    VoxelGrid(sys::o3d_voxelgrid_t, "voxel grid"), new_grid, sys::o3d_voxelgrid_destroy
}

impl VoxelGrid {
    /// True when the cells carry colors (the grid was made from a colored cloud or mesh).
    pub fn has_colors(&self) -> Result<bool> {
        has(sys::o3d_voxelgrid_has_array, self.as_raw(), sys::O3D_VOXELGRID_COLORS)
    }

    /// The occupied cells, sorted by grid index (x, then y, then z).
    pub fn get_voxels(&self) -> Result<Vec<Voxel>> {
        for which in [sys::O3D_VOXELGRID_GRID_INDEX, sys::O3D_VOXELGRID_COLORS] {
            if cols(sys::o3d_voxelgrid_array_shape, self.as_raw(), which)? != 3 {
                return Err(Error::new(ErrorCode::Internal, format!("voxel grid array {which} is not 3 wide")));
            }
        }
        // SAFETY: `out` has room for `cap` rows of 3 values, or is NULL for the count query.
        let index = copy_out::<[i32; 3]>(|out, cap, n| unsafe {
            sys::o3d_voxelgrid_get_index_array(out.cast(), cap, n, self.as_raw(), sys::O3D_VOXELGRID_GRID_INDEX)
        })?;
        // SAFETY: as above.
        let color = copy_out::<[f64; 3]>(|out, cap, n| unsafe {
            sys::o3d_voxelgrid_get_array(out.cast(), cap, n, self.as_raw(), sys::O3D_VOXELGRID_COLORS)
        })?;
        Ok(index.into_iter().zip(color).map(|(grid_index, color)| Voxel { grid_index, color }).collect())
    }

    /// For each query point, whether its cell is occupied.
    pub fn check_if_included(&self, queries: &[[f64; 3]]) -> Result<Vec<bool>> {
        let (mut out, mut n) = (vec![0i32; queries.len()], 0);
        // SAFETY: queries.len() rows of 3 doubles; room for one int per query.
        check(unsafe {
            sys::o3d_voxelgrid_check_if_included(
                out.as_mut_ptr(),
                out.len(),
                &mut n,
                self.as_raw(),
                queries.as_ptr().cast(),
                queries.len(),
            )
        })?;
        out.truncate(n);
        Ok(out.into_iter().map(|v| v != 0).collect())
    }
}

impl fmt::Debug for VoxelGrid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("VoxelGrid")
            .field("voxel_size", &self.voxel_size().unwrap_or(0.0))
            .field("voxels", &self.num_voxels().unwrap_or(0))
            .finish()
    }
}
