//! `VoxelGrid` (o3d.geometry.VoxelGrid): the occupied cells of a regular grid, each with a color.
use std::fmt;
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::adopt;

/// One occupied cell (o3d.geometry.Voxel).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Voxel {
    /// Integer cell coordinates; cell (0,0,0) starts at the grid's origin.
    pub grid_index: [i32; 3],
    /// Mean color of what fell in the cell (0 without colors).
    pub color: [f64; 3],
}

/// A sparse voxel grid of cubes of edge `voxel_size` starting at `origin`.
///
/// Owns an `o3d_voxelgrid_t`; immutable once built, so `Send` and `Sync`.
pub struct VoxelGrid {
    raw: NonNull<sys::o3d_voxelgrid_t>,
}

// SAFETY: every method calls only `const` C functions, which may run concurrently on one handle.
unsafe impl Send for VoxelGrid {}
unsafe impl Sync for VoxelGrid {}

fn new_grid(f: impl FnOnce(*mut *mut sys::o3d_voxelgrid_t) -> sys::o3d_status) -> Result<VoxelGrid> {
    adopt("voxel grid", f, |raw| VoxelGrid { raw })
}

impl VoxelGrid {
    /// The cells holding at least one point; origin = the cloud's min bound - voxel_size / 2.
    pub fn create_from_point_cloud(cloud: &PointCloud, voxel_size: f64) -> Result<VoxelGrid> {
        // SAFETY: valid handle.
        new_grid(|out| unsafe { sys::o3d_voxelgrid_create_from_point_cloud(out, cloud.as_raw(), voxel_size) })
    }

    /// As [`Self::create_from_point_cloud`], on the grid starting at `min_bound`; points outside
    /// `[min_bound, max_bound]` are ignored.
    pub fn create_from_point_cloud_within_bounds(
        cloud: &PointCloud,
        voxel_size: f64,
        min_bound: [f64; 3],
        max_bound: [f64; 3],
    ) -> Result<VoxelGrid> {
        // SAFETY: valid handle; 3 + 3 doubles.
        new_grid(|out| unsafe {
            sys::o3d_voxelgrid_create_from_point_cloud_within_bounds(
                out,
                cloud.as_raw(),
                voxel_size,
                min_bound.as_ptr(),
                max_bound.as_ptr(),
            )
        })
    }

    /// The cells intersecting at least one triangle.
    pub fn create_from_triangle_mesh(mesh: &TriangleMesh, voxel_size: f64) -> Result<VoxelGrid> {
        // SAFETY: valid handle.
        new_grid(|out| unsafe { sys::o3d_voxelgrid_create_from_triangle_mesh(out, mesh.as_raw(), voxel_size) })
    }

    /// Take ownership of a raw handle.
    ///
    /// # Safety
    /// `raw` must be a valid voxel-grid handle owned by the caller; it is destroyed on drop.
    pub unsafe fn from_raw(raw: NonNull<sys::o3d_voxelgrid_t>) -> VoxelGrid {
        VoxelGrid { raw }
    }

    /// The raw handle, still owned by `self`.
    pub fn as_raw(&self) -> *const sys::o3d_voxelgrid_t {
        self.raw.as_ptr()
    }

    /// Edge length of a cell.
    pub fn voxel_size(&self) -> Result<f64> {
        let mut v = 0.0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_voxelgrid_get_voxel_size(&mut v, self.as_raw()) })?;
        Ok(v)
    }

    /// Corner of cell (0,0,0).
    pub fn origin(&self) -> Result<[f64; 3]> {
        let mut v = [0.0; 3];
        // SAFETY: room for 3 doubles.
        check(unsafe { sys::o3d_voxelgrid_get_origin(v.as_mut_ptr(), self.as_raw()) })?;
        Ok(v)
    }

    /// Number of occupied cells.
    pub fn num_voxels(&self) -> Result<usize> {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_voxelgrid_num_voxels(&mut n, self.as_raw()) })?;
        Ok(n)
    }

    /// The occupied cells, sorted by grid index (x, then y, then z).
    pub fn get_voxels(&self) -> Result<Vec<Voxel>> {
        let mut n = 0usize;
        // SAFETY: NULL outputs with capacity 0 only report the count.
        check(unsafe { sys::o3d_voxelgrid_get_voxels(ptr::null_mut(), ptr::null_mut(), 0, &mut n, self.as_raw()) })?;
        let mut index = vec![[0i32; 3]; n];
        let mut color = vec![[0.0f64; 3]; n];
        let mut written = 0usize;
        // SAFETY: room for n rows of 3 ints and n rows of 3 doubles.
        check(unsafe {
            sys::o3d_voxelgrid_get_voxels(index.as_mut_ptr().cast(), color.as_mut_ptr().cast(), n, &mut written,
                self.as_raw(), )
        })?;
        Ok(index.into_iter().zip(color).take(written).map(|(grid_index, color)| Voxel { grid_index, color }).collect())
    }

    /// Grid index of the cell containing `point` (occupied or not).
    pub fn get_voxel(&self, point: [f64; 3]) -> Result<[i32; 3]> {
        let mut out = [0i32; 3];
        // SAFETY: 3 doubles in, room for 3 ints out.
        check(unsafe { sys::o3d_voxelgrid_get_voxel(out.as_mut_ptr(), self.as_raw(), point.as_ptr()) })?;
        Ok(out)
    }

    /// For each query point, whether its cell is occupied.
    pub fn check_if_included(&self, queries: &[[f64; 3]]) -> Result<Vec<bool>> {
        let mut out = vec![0i32; queries.len()];
        // SAFETY: queries.len() rows of 3 doubles; one int out per query.
        check(unsafe {
            sys::o3d_voxelgrid_check_if_included(out.as_mut_ptr(), self.as_raw(), queries.as_ptr().cast(),
                queries.len(), )
        })?;
        Ok(out.into_iter().map(|v| v != 0).collect())
    }
}

impl Drop for VoxelGrid {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once.
        unsafe { sys::o3d_voxelgrid_destroy(self.raw.as_ptr()) }
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
