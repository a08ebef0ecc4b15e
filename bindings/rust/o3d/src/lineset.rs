//! `LineSet` (o3d.geometry.LineSet): points, lines between them and one color per line.
use std::fmt;

use o3d_sys as sys;

use crate::array::{impl_arrays, Family};
use crate::boundingbox::OrientedBoundingBox;
use crate::error::{check, Result};
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::handle;

include!("generated/lineset.rs");

handle! {
    /// Points (N x 3), lines (M pairs of point indices) and optional per-line colors (M x 3, RGB in
    /// `[0, 1]`). Line indices may hold any value; every operation that follows them checks them.
    ///
    /// Owns an `o3d_lineset_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and every
    /// mutation takes `&mut self`, so borrowed views never outlive a mutation.
    LineSet(sys::o3d_lineset_t, "line set"), new_lineset, sys::o3d_lineset_destroy, sys::o3d_lineset_clone
}
impl_arrays!(LineSet, sys::o3d_lineset_t);

/// The float64 arrays (`O3D_LINESET_POINTS`, `O3D_LINESET_COLORS`).
const ARRAYS: Family<sys::o3d_lineset_t, f64> = Family {
    has: sys::o3d_lineset_has_array,
    shape: sys::o3d_lineset_array_shape,
    set: sys::o3d_lineset_set_array,
    get: sys::o3d_lineset_get_array,
    view: sys::o3d_lineset_array_view,
    view_mut: sys::o3d_lineset_array_mutable_view,
    set_f32: Some(sys::o3d_lineset_set_array_f32),
};
/// The int32 array (`O3D_LINESET_LINES`).
const INDICES: Family<sys::o3d_lineset_t, i32> = Family {
    has: sys::o3d_lineset_has_array,
    shape: sys::o3d_lineset_array_shape,
    set: sys::o3d_lineset_set_index_array,
    get: sys::o3d_lineset_get_index_array,
    view: sys::o3d_lineset_index_array_view,
    view_mut: sys::o3d_lineset_index_array_mutable_view,
    set_f32: None,
};

impl LineSet {
    /// A new empty line set.
    pub fn new() -> Result<LineSet> {
        // SAFETY: out-pointer.
        new_lineset(|out| unsafe { sys::o3d_lineset_create(out) })
    }

    /// A line set holding `points` and `lines`.
    pub fn from_points_and_lines(points: &[[f64; 3]], lines: &[[i32; 2]]) -> Result<LineSet> {
        let mut set = LineSet::new()?;
        set.set_points(points)?;
        set.set_lines(lines)?;
        Ok(set)
    }

    /// Replace the points.
    pub fn set_points(&mut self, points: &[[f64; 3]]) -> Result<()> {
        ARRAYS.set(self, sys::O3D_LINESET_POINTS, points)
    }

    /// Replace the points from float32 input (converted in the single copy).
    pub fn set_points_f32(&mut self, points: &[[f32; 3]]) -> Result<()> {
        ARRAYS.set_f32(self, sys::O3D_LINESET_POINTS, points)
    }

    /// Replace the per-line colors.
    pub fn set_colors(&mut self, colors: &[[f64; 3]]) -> Result<()> {
        ARRAYS.set(self, sys::O3D_LINESET_COLORS, colors)
    }

    /// Zero-copy view of the points.
    pub fn points(&self) -> Result<&[[f64; 3]]> {
        ARRAYS.view(self, sys::O3D_LINESET_POINTS)
    }

    /// Zero-copy view of the per-line colors (empty when absent).
    pub fn colors(&self) -> Result<&[[f64; 3]]> {
        ARRAYS.view(self, sys::O3D_LINESET_COLORS)
    }

    /// Copy of the points.
    pub fn points_to_vec(&self) -> Result<Vec<[f64; 3]>> {
        ARRAYS.to_vec(self, sys::O3D_LINESET_POINTS)
    }

    /// Copy of the per-line colors.
    pub fn colors_to_vec(&self) -> Result<Vec<[f64; 3]>> {
        ARRAYS.to_vec(self, sys::O3D_LINESET_COLORS)
    }

    /// Replace the lines (pairs of point indices).
    pub fn set_lines(&mut self, lines: &[[i32; 2]]) -> Result<()> {
        INDICES.set(self, sys::O3D_LINESET_LINES, lines)
    }

    /// Zero-copy view of the lines.
    pub fn lines(&self) -> Result<&[[i32; 2]]> {
        INDICES.view(self, sys::O3D_LINESET_LINES)
    }

    /// Copy of the lines.
    pub fn lines_to_vec(&self) -> Result<Vec<[i32; 2]>> {
        INDICES.to_vec(self, sys::O3D_LINESET_LINES)
    }

    /// The points of `cloud0` then those of `cloud1`, and one line per correspondence
    /// `[index into cloud0, index into cloud1]` (range-checked).
    pub fn create_from_point_cloud_correspondences(
        cloud0: &PointCloud,
        cloud1: &PointCloud,
        correspondences: &[[i32; 2]],
    ) -> Result<LineSet> {
        // SAFETY: valid handles; correspondences.len() pairs of contiguous ints.
        new_lineset(|out| unsafe {
            sys::o3d_lineset_create_from_point_cloud_correspondences(
                out,
                cloud0.as_raw(),
                cloud1.as_raw(),
                correspondences.as_ptr().cast(),
                correspondences.len(),
            )
        })
    }

    /// The 12 edges of an oriented box (points in `get_box_points` order).
    pub fn create_from_oriented_bounding_box(obb: &OrientedBoundingBox) -> Result<LineSet> {
        let raw = obb.to_raw();
        // SAFETY: valid struct.
        new_lineset(|out| unsafe { sys::o3d_lineset_create_from_oriented_bounding_box(out, &raw) })
    }
}

impl fmt::Debug for LineSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("LineSet")
            .field("points", &self.num_points().unwrap_or(0))
            .field("lines", &self.num_lines().unwrap_or(0))
            .finish()
    }
}
