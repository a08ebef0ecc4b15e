//! `LineSet` (o3d.geometry.LineSet): points, lines between them and one color per line.
use std::fmt;
use std::ptr::{self, NonNull};
use std::slice;

use o3d_sys as sys;

use crate::boundingbox::OrientedBoundingBox;
use crate::error::{check, Result};
use crate::pointcloud::{copy_out, PointCloud};
use crate::trianglemesh::TriangleMesh;
use crate::util::{adopt, mat4_ptr};

/// Points (N x 3), lines (M pairs of point indices) and optional per-line colors (M x 3, RGB in
/// `[0, 1]`). Line indices may hold any value; every operation that follows them checks them.
///
/// Owns an `o3d_lineset_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and every
/// mutation takes `&mut self`, so borrowed views never outlive a mutation.
pub struct LineSet {
    raw: NonNull<sys::o3d_lineset_t>,
}

// SAFETY: see the type's documentation.
unsafe impl Send for LineSet {}
unsafe impl Sync for LineSet {}

fn new_lineset(f: impl FnOnce(*mut *mut sys::o3d_lineset_t) -> sys::o3d_status) -> Result<LineSet> {
    adopt("line set", f, |raw| LineSet { raw })
}

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

    /// Take ownership of a raw handle.
    ///
    /// # Safety
    /// `raw` must be a valid line-set handle owned by the caller; it is destroyed on drop.
    pub unsafe fn from_raw(raw: NonNull<sys::o3d_lineset_t>) -> LineSet {
        LineSet { raw }
    }

    /// The raw handle, still owned by `self`.
    pub fn as_raw(&self) -> *const sys::o3d_lineset_t {
        self.raw.as_ptr()
    }

    fn raw_mut(&mut self) -> *mut sys::o3d_lineset_t {
        self.raw.as_ptr()
    }

    /// Deep copy.
    pub fn try_clone(&self) -> Result<LineSet> {
        // SAFETY: valid source handle.
        new_lineset(|out| unsafe { sys::o3d_lineset_clone(out, self.as_raw()) })
    }

    /// Number of points.
    pub fn num_points(&self) -> Result<usize> {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_lineset_num_points(&mut n, self.as_raw()) })?;
        Ok(n)
    }

    /// Number of lines.
    pub fn num_lines(&self) -> Result<usize> {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_lineset_num_lines(&mut n, self.as_raw()) })?;
        Ok(n)
    }

    fn set_f64(&mut self, which: i32, rows: &[[f64; 3]]) -> Result<()> {
        // SAFETY: rows.len() rows of 3 contiguous doubles; copied by the library.
        check(unsafe { sys::o3d_lineset_set_array(self.raw_mut(), which, rows.as_ptr().cast(), rows.len()) })
    }

    fn view_f64(&self, which: i32) -> Result<&[[f64; 3]]> {
        let (mut data, mut n) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_lineset_array_view(&mut data, &mut n, self.as_raw(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&[]);
        }
        // SAFETY: n rows of 3 doubles, valid until the next mutation, which needs `&mut self`.
        Ok(unsafe { slice::from_raw_parts(data.cast::<[f64; 3]>(), n) })
    }

    fn get_f64(&self, which: i32) -> Result<Vec<[f64; 3]>> {
        // SAFETY: `out` has room for `cap` rows of 3 doubles, or is NULL for the count query.
        copy_out::<[f64; 3]>(|out, cap, n| unsafe {
            sys::o3d_lineset_get_array(out.cast(), cap, n, self.as_raw(), which)
        })
    }

    /// Replace the points.
    pub fn set_points(&mut self, points: &[[f64; 3]]) -> Result<()> {
        self.set_f64(sys::O3D_LINESET_POINTS, points)
    }

    /// Replace the per-line colors.
    pub fn set_colors(&mut self, colors: &[[f64; 3]]) -> Result<()> {
        self.set_f64(sys::O3D_LINESET_COLORS, colors)
    }

    /// Zero-copy view of the points.
    pub fn points(&self) -> Result<&[[f64; 3]]> {
        self.view_f64(sys::O3D_LINESET_POINTS)
    }

    /// Zero-copy view of the per-line colors (empty when absent).
    pub fn colors(&self) -> Result<&[[f64; 3]]> {
        self.view_f64(sys::O3D_LINESET_COLORS)
    }

    /// Copy of the points.
    pub fn points_to_vec(&self) -> Result<Vec<[f64; 3]>> {
        self.get_f64(sys::O3D_LINESET_POINTS)
    }

    /// Copy of the per-line colors.
    pub fn colors_to_vec(&self) -> Result<Vec<[f64; 3]>> {
        self.get_f64(sys::O3D_LINESET_COLORS)
    }

    /// Replace the lines (pairs of point indices).
    pub fn set_lines(&mut self, lines: &[[i32; 2]]) -> Result<()> {
        // SAFETY: lines.len() rows of 2 contiguous ints; copied by the library.
        check(unsafe { sys::o3d_lineset_set_index_array(self.raw_mut(), O3D_LINESET_LINES, lines.as_ptr().cast(), lines.len()) })
    }

    /// Zero-copy view of the lines.
    pub fn lines(&self) -> Result<&[[i32; 2]]> {
        let (mut data, mut n) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_lineset_index_array_view(&mut data, &mut n, self.as_raw(), O3D_LINESET_LINES) })?;
        if data.is_null() || n == 0 {
            return Ok(&[]);
        }
        // SAFETY: n rows of 2 ints, valid until the next mutation.
        Ok(unsafe { slice::from_raw_parts(data.cast::<[i32; 2]>(), n) })
    }

    /// Copy of the lines.
    pub fn lines_to_vec(&self) -> Result<Vec<[i32; 2]>> {
        // SAFETY: `out` has room for `cap` rows of 2 ints, or is NULL.
        copy_out::<[i32; 2]>(|out, cap, n| unsafe { sys::o3d_lineset_get_index_array(out.cast(), cap, n, self.as_raw(), O3D_LINESET_LINES) })
    }

    /// Set every line's color to `rgb`.
    pub fn paint_uniform_color(&mut self, rgb: [f64; 3]) -> Result<&mut Self> {
        // SAFETY: 3 doubles.
        check(unsafe { sys::o3d_lineset_paint_uniform_color(self.raw_mut(), rgb.as_ptr()) })?;
        Ok(self)
    }

    /// Apply a row-major 4x4 transform to the points.
    pub fn transform(&mut self, transformation: &[[f64; 4]; 4]) -> Result<&mut Self> {
        // SAFETY: 16 contiguous doubles.
        check(unsafe { sys::o3d_lineset_transform(self.raw_mut(), mat4_ptr(transformation)) })?;
        Ok(self)
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

    /// The 12 edges of the axis-aligned box `[min_bound, max_bound]`.
    pub fn create_from_axis_aligned_bounding_box(min_bound: [f64; 3], max_bound: [f64; 3]) -> Result<LineSet> {
        // SAFETY: 3 + 3 doubles.
        new_lineset(|out| unsafe {
            sys::o3d_lineset_create_from_axis_aligned_bounding_box(out, min_bound.as_ptr(), max_bound.as_ptr())
        })
    }

    /// The mesh's unique edges (each once), on its vertices.
    pub fn create_from_triangle_mesh(mesh: &TriangleMesh) -> Result<LineSet> {
        // SAFETY: valid handle.
        new_lineset(|out| unsafe { sys::o3d_lineset_create_from_triangle_mesh(out, mesh.as_raw()) })
    }
}

impl Drop for LineSet {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once.
        unsafe { sys::o3d_lineset_destroy(self.raw.as_ptr()) }
    }
}

impl Clone for LineSet {
    /// Deep copy. Panics if the library cannot copy; see [`LineSet::try_clone`].
    fn clone(&self) -> Self {
        self.try_clone().unwrap_or_else(|e| panic!("o3d_lineset_clone failed: {e}"))
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
