//! `SelectionPolygonVolume` (o3d.visualization.SelectionPolygonVolume): a prism over a polygon whose
//! extent along the orthogonal axis is `[axis_min, axis_max]`; cropping keeps what lies inside. The
//! reader, getters, setters and crops are generated; written here: the variable-length arrays.
use std::fmt;
use std::path::Path;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::io::c_path;
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::{c_enum, copy_out, handle};

include!("generated/selection.rs");

handle! {
    /// The polygon lies across [`Self::get_orthogonal_axis`]; its corners' coordinate along that axis is
    /// ignored.
    ///
    /// Owns an `o3d_selection_polygon_volume_t`. `Send` and `Sync`: `&self` methods only make `const`
    /// C calls and every change takes `&mut self`.
    SelectionPolygonVolume(sys::o3d_selection_polygon_volume_t, "selection polygon volume"), new_volume,
    sys::o3d_selection_polygon_volume_destroy
}

impl SelectionPolygonVolume {
    /// The polygon's corners, in order.
    pub fn get_bounding_polygon(&self) -> Result<Vec<[f64; 3]>> {
        // SAFETY: a valid handle; `out` holds `cap` rows of 3 doubles.
        copy_out(|out: *mut [f64; 3], cap, n| unsafe {
            sys::o3d_selection_polygon_volume_get_bounding_polygon(out.cast(), cap, n, self.as_raw())
        })
    }

    /// Replace the corners (in order around the polygon; cropping needs 3 or more).
    pub fn set_bounding_polygon(&mut self, corners: &[[f64; 3]]) -> Result<()> {
        // SAFETY: a valid handle and `corners.len()` rows of 3 doubles.
        check(unsafe {
            sys::o3d_selection_polygon_volume_set_bounding_polygon(
                self.raw_mut(),
                corners.as_ptr().cast(),
                corners.len(),
            )
        })
    }

    /// crop_in_polygon: indices of the points of `pc` inside, ascending.
    pub fn crop_in_polygon(&self, pc: &PointCloud) -> Result<Vec<usize>> {
        // SAFETY: valid handles; `out` holds `cap` indices.
        let idx = copy_out(|out: *mut i32, cap, n| unsafe {
            sys::o3d_selection_polygon_volume_crop_in_polygon(out, cap, n, self.as_raw(), pc.as_raw())
        })?;
        Ok(idx.into_iter().map(|i| i as usize).collect())
    }
}

impl fmt::Debug for SelectionPolygonVolume {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SelectionPolygonVolume")
            .field("orthogonal_axis", &self.get_orthogonal_axis().ok())
            .field("axis_min", &self.get_axis_min().ok())
            .field("axis_max", &self.get_axis_max().ok())
            .field("corners", &self.get_bounding_polygon().map(|c| c.len()).unwrap_or(0))
            .finish()
    }
}
