//! `VoxelGrid` (o3d.geometry.VoxelGrid): the occupied cells of a regular grid, each with a color.
use std::fmt;

use o3d_sys as sys;

use crate::array::{cols, has};
use crate::camera::PinholeCameraParameters;
use crate::error::{check, Error, ErrorCode, Result};
use crate::image::Image;
use crate::octree::Octree;
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::{copy_out, handle, mat4_ptr};

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
    /// Owns an `o3d_voxelgrid_t`. `Send` and `Sync`: `&self` methods only make `const` C calls; editing
    /// (add_voxel, remove_voxel, carving) takes `&mut self`.
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

    /// Add `voxel`, replacing the one at its grid index (Open3D's `add_voxel`).
    pub fn add_voxel(&mut self, voxel: Voxel) -> Result<&mut Self> {
        // SAFETY: a valid handle; 3 ints and 3 doubles that live for the call.
        check(unsafe {
            sys::o3d_voxelgrid_add_voxel(self.raw_mut(), voxel.grid_index.as_ptr(), voxel.color.as_ptr())
        })?;
        Ok(self)
    }

    /// Remove the voxel at `idx`; nothing happens when there is none (Open3D's `remove_voxel`).
    pub fn remove_voxel(&mut self, idx: [i32; 3]) -> Result<&mut Self> {
        // SAFETY: a valid handle; 3 ints that live for the call.
        check(unsafe { sys::o3d_voxelgrid_remove_voxel(self.raw_mut(), idx.as_ptr()) })?;
        Ok(self)
    }

    /// The centre of cell `idx`, occupied or not.
    pub fn get_voxel_center_coordinate(&self, idx: [i32; 3]) -> Result<[f64; 3]> {
        let mut out = [0.0; 3];
        // SAFETY: room for 3 doubles; 3 ints in.
        check(unsafe {
            sys::o3d_voxelgrid_get_voxel_center_coordinate(out.as_mut_ptr(), self.as_raw(), idx.as_ptr())
        })?;
        Ok(out)
    }

    /// The 8 corners of cell `index` (its centre +- half a voxel), in Open3D's order.
    pub fn get_voxel_bounding_points(&self, index: [i32; 3]) -> Result<[[f64; 3]; 8]> {
        let mut out = [[0.0; 3]; 8];
        // SAFETY: room for 8 rows of 3 contiguous doubles; 3 ints in.
        check(unsafe {
            sys::o3d_voxelgrid_get_voxel_bounding_points(out.as_mut_ptr().cast(), self.as_raw(), index.as_ptr())
        })?;
        Ok(out)
    }

    /// Space carving with a 1-channel float32 depth map in metres of the intrinsic's size (Open3D's
    /// `carve_depth_map`): a voxel stays when a corner inside the image lies on or behind the observed depth,
    /// or, with `keep_voxels_outside_image`, when a corner falls outside the image. The extrinsic (world to
    /// camera) must be rigid.
    pub fn carve_depth_map(
        &mut self,
        depth_map: &Image,
        camera_params: &PinholeCameraParameters,
        keep_voxels_outside_image: bool,
    ) -> Result<&mut Self> {
        let intrinsic = camera_params.intrinsic.to_raw();
        // SAFETY: valid handles; the struct and 16 doubles live for the call.
        check(unsafe {
            sys::o3d_voxelgrid_carve_depth_map(
                self.raw_mut(),
                depth_map.as_raw(),
                &intrinsic,
                mat4_ptr(&camera_params.extrinsic),
                i32::from(keep_voxels_outside_image),
            )
        })?;
        Ok(self)
    }

    /// Space carving with a 1-channel float32 mask of the intrinsic's size (Open3D's `carve_silhouette`): as
    /// [`VoxelGrid::carve_depth_map`], a voxel staying when a corner inside the image falls on the mask (> 0).
    pub fn carve_silhouette(
        &mut self,
        silhouette_mask: &Image,
        camera_params: &PinholeCameraParameters,
        keep_voxels_outside_image: bool,
    ) -> Result<&mut Self> {
        let intrinsic = camera_params.intrinsic.to_raw();
        // SAFETY: valid handles; the struct and 16 doubles live for the call.
        check(unsafe {
            sys::o3d_voxelgrid_carve_silhouette(
                self.raw_mut(),
                silhouette_mask.as_raw(),
                &intrinsic,
                mat4_ptr(&camera_params.extrinsic),
                i32::from(keep_voxels_outside_image),
            )
        })?;
        Ok(self)
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
