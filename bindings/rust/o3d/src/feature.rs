//! `Feature` (o3d.pipelines.registration.Feature): a `dimension` x `num` matrix of per-point
//! descriptors, FPFH, feature matching and the feature files (o3d.io.read_feature / write_feature).
use std::fmt;
use std::path::Path;
use std::ptr::{self, NonNull};
use std::slice;

use o3d_sys as sys;

use crate::array::Family;
use crate::error::{check, Error, ErrorCode, Result};
use crate::io::c_path;
use crate::pointcloud::{PointCloud, SearchParam};
use crate::util::{adopt, to_i32};

/// Per-point descriptors stored descriptor by descriptor: descriptor `i` is
/// `data()[i * dimension..(i + 1) * dimension]` (Open3D's column-major Eigen matrix).
///
/// Owns an `o3d_feature_t`. `Send` and `Sync`: `&self` methods only read (the data view is taken
/// when the feature is made or resized, both of which need the feature exclusively).
pub struct Feature {
    raw: NonNull<sys::o3d_feature_t>,
    // The library's buffer (NULL when empty), valid until the next resize or the drop; refreshed
    // by every call that may move it, so reading it needs no C call.
    data: *mut f64,
    dimension: usize,
    num: usize,
}

// SAFETY: the C API lets a handle be used from any thread; `&self` methods make only `const`
// calls or read the cached view, and every mutation takes `&mut self`.
unsafe impl Send for Feature {}
unsafe impl Sync for Feature {}

impl crate::array::Arrays for Feature {
    type Raw = sys::o3d_feature_t;
    fn handle(&self) -> *const sys::o3d_feature_t {
        self.raw.as_ptr()
    }
    fn handle_mut(&mut self) -> *mut sys::o3d_feature_t {
        self.raw.as_ptr()
    }
}

/// The descriptor matrix (`O3D_FEATURE_DATA`, num x dimension).
const ARRAYS: Family<sys::o3d_feature_t, f64> = Family {
    has: sys::o3d_feature_has_array,
    shape: sys::o3d_feature_array_shape,
    set: sys::o3d_feature_set_array,
    get: sys::o3d_feature_get_array,
    view: sys::o3d_feature_array_view,
    view_mut: sys::o3d_feature_array_mutable_view,
    set_f32: Some(sys::o3d_feature_set_array_f32),
};

impl Feature {
    /// Wrap a new handle and take its view.
    fn adopt(f: impl FnOnce(*mut *mut sys::o3d_feature_t) -> sys::o3d_status) -> Result<Feature> {
        let mut feature = adopt("feature", f, |raw| Feature { raw, data: ptr::null_mut(), dimension: 0, num: 0 })?;
        feature.refresh()?;
        Ok(feature)
    }

    /// Re-read the shape and the data pointer (after construction or resize).
    fn refresh(&mut self) -> Result<()> {
        let h = self.raw.as_ptr();
        let (mut dimension, mut num, mut data) = (0, 0, ptr::null_mut());
        // SAFETY: valid handle and out-pointers; we hold the feature exclusively.
        unsafe {
            check(sys::o3d_feature_dimension(&mut dimension, h))?;
            check(sys::o3d_feature_num(&mut num, h))?;
            check(sys::o3d_feature_array_mutable_view(&mut data, &mut 0, h, sys::O3D_FEATURE_DATA))?;
        }
        if data.is_null() && dimension * num != 0 {
            return Err(Error::new(
                ErrorCode::Internal,
                "o3d_feature_array_mutable_view gave NULL for a non-empty feature",
            ));
        }
        (self.dimension, self.num, self.data) = (dimension, num, data);
        Ok(())
    }

    /// A `dimension` x `num` feature, all zeros.
    pub fn new(dimension: usize, num: usize) -> Result<Feature> {
        // SAFETY: out-pointer provided by adopt.
        Feature::adopt(|out| unsafe { sys::o3d_feature_create(out, dimension, num) })
    }

    /// A feature holding a copy of `data`, `dimension` values per descriptor (so
    /// `data.len() / dimension` descriptors). A length that is not a multiple of `dimension`, or a
    /// non-finite value, is an error.
    pub fn from_data(data: &[f64], dimension: usize) -> Result<Feature> {
        let num = rows_of(data.len(), dimension)?;
        // SAFETY: data holds dimension * num doubles.
        Feature::adopt(|out| unsafe { sys::o3d_feature_create_from_data(out, data.as_ptr(), dimension, num) })
    }

    /// A feature of `D`-dimensional descriptors, one per row.
    pub fn from_descriptors<const D: usize>(rows: &[[f64; D]]) -> Result<Feature> {
        // SAFETY: rows.len() contiguous rows of D doubles.
        Feature::adopt(|out| unsafe { sys::o3d_feature_create_from_data(out, rows.as_ptr().cast(), D, rows.len()) })
    }

    /// Take ownership of a raw handle (e.g. from `o3d-sys`).
    ///
    /// # Safety
    /// `raw` must be a valid feature handle owned by the caller; it is destroyed on drop, and must
    /// not be resized behind this wrapper's back.
    pub unsafe fn from_raw(raw: NonNull<sys::o3d_feature_t>) -> Result<Feature> {
        let mut feature = Feature { raw, data: ptr::null_mut(), dimension: 0, num: 0 };
        feature.refresh()?;
        Ok(feature)
    }

    /// The raw handle, still owned by `self`.
    pub fn as_raw(&self) -> *const sys::o3d_feature_t {
        self.raw.as_ptr()
    }

    /// Deep copy (`o3d_feature_clone`); [`Clone::clone`] panics where this returns `Err`.
    pub fn try_clone(&self) -> Result<Feature> {
        // SAFETY: valid source handle.
        Feature::adopt(|out| unsafe { sys::o3d_feature_clone(out, self.as_raw()) })
    }

    /// Descriptor length (33 for FPFH).
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// Number of descriptors (points).
    pub fn num(&self) -> usize {
        self.num
    }

    /// True when there are no descriptors.
    pub fn is_empty(&self) -> bool {
        self.num == 0
    }

    /// Zero-copy view of the `dimension * num` values, descriptor by descriptor.
    pub fn data(&self) -> &[f64] {
        let n = self.dimension * self.num;
        if n == 0 {
            return &[];
        }
        // SAFETY: the library's buffer of n doubles, valid until resize/drop (both need &mut self).
        unsafe { slice::from_raw_parts(self.data, n) }
    }

    /// Writable zero-copy view of the values.
    pub fn data_mut(&mut self) -> &mut [f64] {
        let n = self.dimension * self.num;
        if n == 0 {
            return &mut [];
        }
        // SAFETY: as `data`, and `&mut self` makes the view exclusive.
        unsafe { slice::from_raw_parts_mut(self.data, n) }
    }

    /// Descriptor `i`, or `None` past the end.
    pub fn descriptor(&self, i: usize) -> Option<&[f64]> {
        (i < self.num).then(|| &self.data()[i * self.dimension..(i + 1) * self.dimension])
    }

    /// The descriptors in order.
    pub fn descriptors(&self) -> impl Iterator<Item = &[f64]> + '_ {
        (0..self.num).map(move |i| &self.data()[i * self.dimension..(i + 1) * self.dimension])
    }

    /// True when there are descriptors (of a nonzero dimension).
    pub fn has_data(&self) -> Result<bool> {
        ARRAYS.has(self, sys::O3D_FEATURE_DATA)
    }

    /// Replace the descriptors with `data` (whole descriptors of the current dimension; their count
    /// may change). Views taken before are invalidated.
    pub fn set_data(&mut self, data: &[f64]) -> Result<()> {
        let status = ARRAYS.set_flat(self, sys::O3D_FEATURE_DATA, data);
        let refreshed = self.refresh();
        status.and(refreshed)
    }

    /// As [`Self::set_data`] from `D`-dimensional float32 descriptors (`D` must be the dimension).
    pub fn set_descriptors_f32<const D: usize>(&mut self, rows: &[[f32; D]]) -> Result<()> {
        let status = ARRAYS.set_f32(self, sys::O3D_FEATURE_DATA, rows);
        let refreshed = self.refresh();
        status.and(refreshed)
    }

    /// Zero-copy view of the `D`-dimensional descriptors, one row each (`D` must be the dimension).
    pub fn descriptor_rows<const D: usize>(&self) -> Result<&[[f64; D]]> {
        ARRAYS.view(self, sys::O3D_FEATURE_DATA)
    }

    /// Copy of the values (`o3d_feature_get_array`).
    pub fn to_vec(&self) -> Result<Vec<f64>> {
        let (mut out, mut rows) = (vec![0.0; self.dimension * self.num], 0);
        // SAFETY: `out` has room for `num` rows of `dimension` values.
        check(unsafe {
            sys::o3d_feature_get_array(out.as_mut_ptr(), self.num, &mut rows, self.as_raw(), sys::O3D_FEATURE_DATA)
        })?;
        out.truncate(rows * self.dimension);
        Ok(out)
    }

    /// Resize to `dimension` x `num` (Open3D's `Feature.resize`): with the same dimension the kept
    /// descriptors stay, new values are zero. Views taken before are invalidated (the borrow
    /// checker sees to it).
    pub fn resize(&mut self, dimension: usize, num: usize) -> Result<()> {
        // SAFETY: valid handle, held exclusively.
        let status = unsafe { sys::o3d_feature_resize(self.raw.as_ptr(), dimension, num) };
        // Refresh even on failure: the library may have moved the buffer before failing.
        let refreshed = self.refresh();
        check(status)?;
        refreshed
    }

    /// The descriptors of points `indices` (in that order), or with `invert` of every other point
    /// (ascending). An index out of range is an error.
    pub fn select_by_index(&self, indices: &[i64], invert: bool) -> Result<Feature> {
        // SAFETY: indices.len() int64 values; valid handle.
        Feature::adopt(|out| unsafe {
            sys::o3d_feature_select_by_index(out, self.as_raw(), indices.as_ptr(), indices.len(), invert as i32)
        })
    }
}

/// `len / dimension`, or an error when `len` values are not whole rows of `dimension`.
pub(crate) fn rows_of(len: usize, dimension: usize) -> Result<usize> {
    if dimension == 0 {
        return if len == 0 {
            Ok(0)
        } else {
            Err(Error::new(ErrorCode::InvalidArgument, format!("{len} values given for dimension 0")))
        };
    }
    if len % dimension != 0 {
        return Err(Error::new(
            ErrorCode::InvalidArgument,
            format!("{len} values are not a whole number of {dimension}-dimensional rows"),
        ));
    }
    Ok(len / dimension)
}

impl Drop for Feature {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once.
        unsafe { sys::o3d_feature_destroy(self.raw.as_ptr()) }
    }
}

impl Clone for Feature {
    /// Deep copy. Panics if the library cannot copy (out of memory); see [`Feature::try_clone`].
    fn clone(&self) -> Self {
        self.try_clone().unwrap_or_else(|e| panic!("o3d_feature_clone failed: {e}"))
    }
}

impl fmt::Debug for Feature {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Feature").field("dimension", &self.dimension).field("num", &self.num).finish()
    }
}

/// Fast Point Feature Histograms (Rusu et al. 2009) of every point, 33 x N; the cloud needs
/// normals. Open3D's tutorial uses `SearchParam::Hybrid { radius: 0.25, max_nn: 100 }` on a 0.05
/// voxel grid. @see o3d.pipelines.registration.compute_fpfh_feature
pub fn compute_fpfh_feature(cloud: &PointCloud, param: SearchParam) -> Result<Feature> {
    compute_fpfh_feature_with(cloud, param, &[], 0)
}

/// As [`compute_fpfh_feature`], for the points `indices` only (all points when empty): one
/// descriptor per distinct index, in ascending point order (Open3D's mask semantics), equal to the
/// matching descriptors of the whole cloud; on `num_threads` threads (0 = the library default; the
/// result does not depend on it).
pub fn compute_fpfh_feature_with(
    cloud: &PointCloud,
    param: SearchParam,
    indices: &[i64],
    num_threads: usize,
) -> Result<Feature> {
    let p = param.to_raw()?;
    let threads = to_i32(num_threads, "num_threads")?;
    let idx = if indices.is_empty() { ptr::null() } else { indices.as_ptr() };
    // SAFETY: valid handles; indices.len() int64 values or NULL with 0.
    Feature::adopt(|out| unsafe { sys::o3d_compute_fpfh_feature(out, cloud.as_raw(), &p, idx, indices.len(), threads) })
}

/// Options of [`correspondences_from_features`]; `Default` is Open3D's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MatchOptions {
    /// Keep only pairs that are also nearest the other way (default false)...
    pub mutual_filter: bool,
    /// ...unless fewer than this share of the source descriptors survive, in which case every
    /// pair is kept (Open3D's rule; default 0.1).
    pub mutual_consistency_ratio: f64,
    /// Threads; 0 = the library default (default 0).
    pub num_threads: usize,
}

impl Default for MatchOptions {
    fn default() -> Self {
        MatchOptions { mutual_filter: false, mutual_consistency_ratio: 0.1, num_threads: 0 }
    }
}

/// For each source descriptor its nearest target descriptor (L2): `(source, target)` pairs in
/// ascending source order. Dimensions must agree.
/// @see o3d.pipelines.registration.correspondences_from_features
pub fn correspondences_from_features(
    source: &Feature,
    target: &Feature,
    options: &MatchOptions,
) -> Result<Vec<[i32; 2]>> {
    let threads = to_i32(options.num_threads, "num_threads")?;
    // At most one pair per source descriptor: one call with room for all of them.
    let mut out = vec![[0i32; 2]; source.num()];
    let mut n = 0usize;
    // SAFETY: valid handles; `out` holds out.len() pairs of int32.
    check(unsafe {
        sys::o3d_correspondences_from_features(
            out.as_mut_ptr().cast(),
            out.len(),
            &mut n,
            source.as_raw(),
            target.as_raw(),
            options.mutual_filter as i32,
            options.mutual_consistency_ratio,
            threads,
        )
    })?;
    if n > out.len() {
        return Err(Error::new(ErrorCode::Internal, format!("{n} correspondences for {} descriptors", out.len())));
    }
    out.truncate(n);
    Ok(out)
}

/// Read a feature file in Open3D's binary layout (int32 dimension, int32 num, then the values).
/// Truncated or inconsistent files give [`ErrorCode::Parse`]. @see o3d.io.read_feature
pub fn read_feature(path: impl AsRef<Path>) -> Result<Feature> {
    let path = c_path(path.as_ref())?;
    // SAFETY: NUL-terminated path.
    Feature::adopt(|out| unsafe { sys::o3d_io_read_feature(out, path.as_ptr()) })
}

/// Write `feature` in the layout [`read_feature`] reads. @see o3d.io.write_feature
pub fn write_feature(path: impl AsRef<Path>, feature: &Feature) -> Result<()> {
    let path = c_path(path.as_ref())?;
    // SAFETY: NUL-terminated path, valid handle.
    check(unsafe { sys::o3d_io_write_feature(path.as_ptr(), feature.as_raw()) })
}
