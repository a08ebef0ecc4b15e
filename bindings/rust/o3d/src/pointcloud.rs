//! `PointCloud` (o3d.geometry.PointCloud) and `SearchParam` (KDTreeSearchParam*).
use std::fmt;
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::array::{impl_arrays, Family};
use crate::error::{check, Error, ErrorCode, Result};
use crate::util::{copy_out, handle, index, init_struct, options, to_i32, CField, IndexLists};

include!("generated/pointcloud.rs");

/// Neighbourhood search parameter (Open3D `KDTreeSearchParamKNN` / `Radius` / `Hybrid`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SearchParam {
    /// The `knn` nearest points.
    Knn {
        /// Neighbour count.
        knn: usize,
    },
    /// All points within `radius`.
    Radius {
        /// Search radius, in the units of the cloud.
        radius: f64,
    },
    /// At most `max_nn` nearest points within `radius`.
    Hybrid {
        /// Search radius, in the units of the cloud.
        radius: f64,
        /// Neighbour count limit.
        max_nn: usize,
    },
}

impl Default for SearchParam {
    /// The library's default (`o3d_search_param_init`: KNN with 30 neighbours, Open3D's
    /// `KDTreeSearchParamKNN()`); panics only if the library rejects its own struct.
    fn default() -> Self {
        SearchParam::raw_default()
            .and_then(SearchParam::from_raw)
            .unwrap_or_else(|e| panic!("o3d_search_param_init failed: {e}"))
    }
}

impl SearchParam {
    fn raw_default() -> Result<sys::o3d_search_param_t> {
        // SAFETY: o3d_search_param_t is plain numbers; o3d_search_param_init is its init.
        unsafe { init_struct(|p, n| sys::o3d_search_param_init(p, n)) }
    }

    fn from_raw(raw: sys::o3d_search_param_t) -> Result<SearchParam> {
        let count = |n: i32| n.max(0) as usize;
        Ok(match raw.kind {
            sys::O3D_SEARCH_KNN => SearchParam::Knn { knn: count(raw.knn) },
            sys::O3D_SEARCH_RADIUS => SearchParam::Radius { radius: raw.radius },
            sys::O3D_SEARCH_HYBRID => SearchParam::Hybrid { radius: raw.radius, max_nn: count(raw.knn) },
            other => return Err(Error::new(ErrorCode::Internal, format!("unknown search kind {other}"))),
        })
    }

    /// The C struct, started from `o3d_search_param_init` so `struct_size` is right.
    pub(crate) fn to_raw(self) -> Result<sys::o3d_search_param_t> {
        let mut raw = SearchParam::raw_default()?;
        let count = |n: usize| to_i32(n, "neighbour count");
        match self {
            SearchParam::Knn { knn } => {
                raw.kind = sys::O3D_SEARCH_KNN;
                raw.knn = count(knn)?;
            }
            SearchParam::Radius { radius } => {
                raw.kind = sys::O3D_SEARCH_RADIUS;
                raw.radius = radius;
            }
            SearchParam::Hybrid { radius, max_nn } => {
                raw.kind = sys::O3D_SEARCH_HYBRID;
                raw.radius = radius;
                raw.knn = count(max_nn)?;
            }
        }
        Ok(raw)
    }
}

/// A search held by an options struct (e.g. [`PlanarPatchOptions::search_param`]).
impl CField<sys::o3d_search_param_t> for SearchParam {
    fn to_c(&self, _: &str) -> Result<sys::o3d_search_param_t> {
        self.to_raw()
    }
    fn from_c(c: sys::o3d_search_param_t) -> Result<Self> {
        SearchParam::from_raw(c)
    }
}

/// What [`PointCloud::voxel_down_sample_and_trace`] returns (Open3D's tuple).
#[derive(Debug)]
pub struct VoxelDownSampleTrace {
    /// One mean point per occupied voxel, sorted by voxel (z, y, x).
    pub cloud: PointCloud,
    /// Per output point, per octant of its voxel (bit 0, 1, 2: the upper half along x, y, z), the
    /// largest input index in that octant, if any.
    pub cubic_ids: Vec<[Option<usize>; 8]>,
    /// Per output point, the input indices it averages (ascending).
    pub original_indices: Vec<Vec<usize>>,
}

handle! {
    /// A point cloud: points, and optionally one normal, one color (RGB in `[0, 1]`) and one
    /// covariance (row-major 3x3) per point.
    ///
    /// Owns an `o3d_pointcloud_t`. `Send` and `Sync`: `&self` methods only read (the C API allows
    /// concurrent `const` calls), every mutation takes `&mut self`.
    PointCloud(sys::o3d_pointcloud_t, "cloud"), new_cloud, sys::o3d_pointcloud_destroy, sys::o3d_pointcloud_clone
}
impl_arrays!(PointCloud, sys::o3d_pointcloud_t);

/// The cloud's float64 arrays (`O3D_POINTCLOUD_*`).
const ARRAYS: Family<sys::o3d_pointcloud_t, f64> = Family {
    has: sys::o3d_pointcloud_has_array,
    shape: sys::o3d_pointcloud_array_shape,
    set: sys::o3d_pointcloud_set_array,
    get: sys::o3d_pointcloud_get_array,
    view: sys::o3d_pointcloud_array_view,
    view_mut: sys::o3d_pointcloud_array_mutable_view,
    set_f32: Some(sys::o3d_pointcloud_set_array_f32),
};
const POINTS: i32 = sys::O3D_POINTCLOUD_POINTS;
const NORMALS: i32 = sys::O3D_POINTCLOUD_NORMALS;
const COLORS: i32 = sys::O3D_POINTCLOUD_COLORS;
const COVARIANCES: i32 = sys::O3D_POINTCLOUD_COVARIANCES;

/// Own a cloud a successful C call wrote (none → Internal error).
fn owned(raw: Option<NonNull<sys::o3d_pointcloud_t>>) -> Result<PointCloud> {
    // SAFETY: `out` is the constructor's out-pointer.
    new_cloud(|out| unsafe {
        *out = raw.map_or(ptr::null_mut(), NonNull::as_ptr);
        sys::O3D_OK
    })
}

/// A row-major 3x3 matrix.
type Mat3 = [[f64; 3]; 3];

/// The value of `r`, or a panic naming the C function that refused (the non-`try_` accessors).
fn or_panic<T>(r: Result<T>, what: &str) -> T {
    r.unwrap_or_else(|e| panic!("{what} failed: {e}"))
}

/// The accessors of one N x 3 float64 array of the cloud (`$which`, named `$what` in the docs).
macro_rules! xyz_array {
    ($which:expr, $what:literal, $has:ident, $set:ident, $set_f32:ident, $try_view:ident, $view:ident,
     $try_view_mut:ident, $view_mut:ident, $to_vec:ident) => {
        #[doc = concat!("True if the cloud has ", $what, " (one per point for normals and colors).")]
        pub fn $has(&self) -> Result<bool> {
            ARRAYS.has(self, $which)
        }

        #[doc = concat!("Replace the ", $what, " (copied once); the other arrays are kept as they are.")]
        pub fn $set(&mut self, rows: &[[f64; 3]]) -> Result<()> {
            ARRAYS.set(self, $which, rows)
        }

        #[doc = concat!("Replace the ", $what, " from float32 input (converted in the single copy).")]
        pub fn $set_f32(&mut self, rows: &[[f32; 3]]) -> Result<()> {
            ARRAYS.set_f32(self, $which, rows)
        }

        #[doc = concat!("Zero-copy view of the ", $what, ", borrowed from the cloud (empty when it has none).")]
        pub fn $try_view(&self) -> Result<&[[f64; 3]]> {
            ARRAYS.view(self, $which)
        }

        #[doc = concat!("Zero-copy view of the ", $what, ". Panics if the library refuses (see `", stringify!($try_view), "`).")]
        pub fn $view(&self) -> &[[f64; 3]] {
            or_panic(self.$try_view(), "o3d_pointcloud_array_view")
        }

        #[doc = concat!("Writable zero-copy view of the ", $what, ", for in-place edits.")]
        pub fn $try_view_mut(&mut self) -> Result<&mut [[f64; 3]]> {
            ARRAYS.view_mut(self, $which)
        }

        #[doc = concat!("Writable zero-copy view of the ", $what, ". Panics if the library refuses.")]
        pub fn $view_mut(&mut self) -> &mut [[f64; 3]] {
            or_panic(self.$try_view_mut(), "o3d_pointcloud_array_mutable_view")
        }

        #[doc = concat!("Copy of the ", $what, " (`o3d_pointcloud_get_array`).")]
        pub fn $to_vec(&self) -> Result<Vec<[f64; 3]>> {
            ARRAYS.to_vec(self, $which)
        }
    };
}

impl PointCloud {
    xyz_array! {
        POINTS, "points",
        has_points, set_points, set_points_f32, try_points, points, try_points_mut, points_mut, points_to_vec
    }
    xyz_array! {
        NORMALS, "normals",
        has_normals, set_normals, set_normals_f32, try_normals, normals, try_normals_mut, normals_mut, normals_to_vec
    }
    xyz_array! {
        COLORS, "colors (RGB in `[0, 1]`)",
        has_colors, set_colors, set_colors_f32, try_colors, colors, try_colors_mut, colors_mut, colors_to_vec
    }
}

impl PointCloud {
    /// A new empty cloud.
    pub fn new() -> Result<PointCloud> {
        // SAFETY: out-pointer provided by new_cloud.
        new_cloud(|out| unsafe { sys::o3d_pointcloud_create(out) })
    }

    /// A new cloud holding `points`.
    pub fn from_points(points: &[[f64; 3]]) -> Result<PointCloud> {
        let mut pc = PointCloud::new()?;
        pc.set_points(points)?;
        Ok(pc)
    }

    /// Number of points. Panics if the library refuses (it only does for a NULL handle).
    pub fn len(&self) -> usize {
        or_panic(self.try_len(), "o3d_pointcloud_size")
    }

    /// True when the cloud has no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// True when the cloud has one covariance per point.
    pub fn has_covariances(&self) -> Result<bool> {
        ARRAYS.has(self, COVARIANCES)
    }

    /// Replace the covariances (copied once; each must be symmetric).
    pub fn set_covariances(&mut self, covariances: &[Mat3]) -> Result<()> {
        ARRAYS.set(self, COVARIANCES, covariances)
    }

    /// Zero-copy view of the covariances (empty when the cloud has none), borrowed from the cloud.
    pub fn covariances(&self) -> Result<&[Mat3]> {
        ARRAYS.view(self, COVARIANCES)
    }

    /// Copy of the covariances.
    pub fn covariances_to_vec(&self) -> Result<Vec<Mat3>> {
        ARRAYS.to_vec(self, COVARIANCES)
    }

    /// Covariance of each point's neighbourhood (divided by the neighbour count; fewer than 3
    /// neighbours give the identity, as Open3D). `SearchParam::default()` is Open3D's KNN 30.
    pub fn estimate_covariances(&mut self, param: SearchParam) -> Result<&mut Self> {
        let raw = param.to_raw()?;
        // SAFETY: valid handle and parameter struct.
        check(unsafe { sys::o3d_pointcloud_estimate_covariances(self.raw_mut(), &raw) })?;
        Ok(self)
    }

    /// Each point's neighbourhood covariance (divided by the count, the point itself included; fewer
    /// than 3 neighbours give the identity), without changing `input` (Open3D's static
    /// `PointCloud.estimate_point_covariances`; `SearchParam::default()` is its KNN 30).
    pub fn estimate_point_covariances(input: &PointCloud, param: SearchParam) -> Result<Vec<Mat3>> {
        let raw = param.to_raw()?;
        // SAFETY: `out` has room for `cap` matrices of 9 contiguous doubles or is NULL.
        copy_out::<Mat3>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_estimate_point_covariances(out.cast(), cap, n, input.as_raw(), &raw, 0)
        })
    }

    /// Moving-least-squares smoothing: each point projected onto the weighted PCA plane of its
    /// neighbourhood (Open3D's default search: [`SearchParam::Hybrid`] radius 0.05, 30 neighbours).
    pub fn smooth_mls(&self, param: SearchParam) -> Result<PointCloud> {
        let raw = param.to_raw()?;
        // SAFETY: valid handle and parameter struct.
        new_cloud(|out| unsafe { sys::o3d_pointcloud_smooth_mls(out, self.as_raw(), &raw) })
    }

    /// Bilateral smoothing (one pass): neighbours weighted by distance (`sigma_s`) and by their offset
    /// along the point's normal (`sigma_r`). Open3D's defaults: hybrid 0.05 / 30, 0.05, 0.05.
    pub fn smooth_bilateral(&self, param: SearchParam, sigma_s: f64, sigma_r: f64) -> Result<PointCloud> {
        let raw = param.to_raw()?;
        // SAFETY: valid handle and parameter struct.
        new_cloud(|out| unsafe { sys::o3d_pointcloud_smooth_bilateral(out, self.as_raw(), &raw, sigma_s, sigma_r) })
    }

    /// Voxel down-sampling that remembers where each output point came from (Open3D's
    /// `voxel_down_sample_and_trace`); voxel (i, j, k) spans `min_bound + voxel_size * [i, i + 1) x ...`.
    /// With `approximate_class` colors are classes (the most frequent integer red value) instead of means.
    pub fn voxel_down_sample_and_trace(
        &self,
        voxel_size: f64,
        min_bound: [f64; 3],
        max_bound: [f64; 3],
        approximate_class: bool,
    ) -> Result<VoxelDownSampleTrace> {
        let (mut cloud, mut cubic, mut original) = (ptr::null_mut(), ptr::null_mut(), ptr::null_mut());
        // SAFETY: valid handle; 3 + 3 doubles; three out-pointers.
        let status = unsafe {
            sys::o3d_pointcloud_voxel_down_sample_and_trace(
                &mut cloud,
                &mut cubic,
                &mut original,
                self.as_raw(),
                voxel_size,
                min_bound.as_ptr(),
                max_bound.as_ptr(),
                i32::from(approximate_class),
            )
        };
        // Own all three before looking at the status, so nothing leaks.
        let (cubic, original) = (IndexLists(cubic), IndexLists(original));
        let cloud = NonNull::new(cloud);
        check(status)?;
        let cloud = owned(cloud)?;
        let cubic_ids = cubic
            .to_vecs()?
            .into_iter()
            .map(|ids| {
                let ids: [i32; 8] = ids.try_into().map_err(|_| {
                    Error::new(ErrorCode::Internal, "the library returned a cubic-id list without 8 entries")
                })?;
                Ok(ids.map(|i| usize::try_from(i).ok()))
            })
            .collect::<Result<Vec<_>>>()?;
        let original_indices = original
            .to_vecs()?
            .into_iter()
            .map(|list| list.into_iter().map(index).collect())
            .collect::<Result<Vec<_>>>()?;
        Ok(VoxelDownSampleTrace { cloud, cubic_ids, original_indices })
    }

    /// Axis-aligned bounding box as (min corner, max corner).
    pub fn get_axis_aligned_bounding_box(&self) -> Result<([f64; 3], [f64; 3])> {
        let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
        // SAFETY: room for 3 + 3 doubles.
        check(unsafe {
            sys::o3d_pointcloud_get_axis_aligned_bounding_box(lo.as_mut_ptr(), hi.as_mut_ptr(), self.as_raw())
        })?;
        Ok((lo, hi))
    }

    /// New cloud with the points at `indices` (or all others when `invert`). Out of range → Err.
    pub fn select_by_index(&self, indices: &[i32], invert: bool) -> Result<PointCloud> {
        // SAFETY: indices.len() ints.
        new_cloud(|out| unsafe {
            sys::o3d_pointcloud_select_by_index(out, self.as_raw(), indices.as_ptr(), indices.len(), invert as i32)
        })
    }

    /// PCA normals over each point's neighbourhood. Existing normals orient the new ones.
    /// Uses the library's default thread count ([`crate::set_num_threads`]).
    pub fn estimate_normals(&mut self, param: SearchParam) -> Result<&mut Self> {
        let raw = param.to_raw()?;
        // SAFETY: valid handle and parameter struct.
        check(unsafe { sys::o3d_pointcloud_estimate_normals(self.raw_mut(), &raw, 0) })?;
        Ok(self)
    }

    /// Flip normals to have a non-negative dot product with `direction` (Open3D default: +Z).
    pub fn orient_normals_to_align_with_direction(&mut self, direction: [f64; 3]) -> Result<&mut Self> {
        // SAFETY: 3 doubles.
        check(unsafe {
            sys::o3d_pointcloud_orient_normals_to_align_with_direction(self.raw_mut(), direction.as_ptr())
        })?;
        Ok(self)
    }

    /// Flip normals to point towards `camera_location` (Open3D default: the origin).
    pub fn orient_normals_towards_camera_location(&mut self, camera_location: [f64; 3]) -> Result<&mut Self> {
        // SAFETY: 3 doubles.
        check(unsafe {
            sys::o3d_pointcloud_orient_normals_towards_camera_location(self.raw_mut(), camera_location.as_ptr())
        })?;
        Ok(self)
    }

    /// Distance from each point to its nearest other point.
    pub fn compute_nearest_neighbor_distance(&self) -> Result<Vec<f64>> {
        // SAFETY: `out` has room for `cap` doubles or is NULL.
        copy_out::<f64>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_compute_nearest_neighbor_distance(out, cap, n, self.as_raw(), 0)
        })
    }

    /// For each point of `self`, the distance to the closest point of `target`.
    pub fn compute_point_cloud_distance(&self, target: &PointCloud) -> Result<Vec<f64>> {
        // SAFETY: `out` has room for `cap` doubles or is NULL.
        copy_out::<f64>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_compute_point_cloud_distance(out, cap, n, self.as_raw(), target.as_raw(), 0)
        })
    }

    /// Run a C call writing point indices (at most one per point) into a buffer of `len()` slots.
    fn indices(&self, f: impl FnOnce(*mut i32, usize, *mut usize) -> sys::o3d_status) -> Result<Vec<i32>> {
        let cap = self.try_len()?;
        let mut out = vec![0i32; cap];
        let mut n = 0usize;
        check(f(out.as_mut_ptr(), cap, &mut n))?;
        out.truncate(n.min(cap));
        Ok(out)
    }

    /// Statistical outlier removal: drop points whose mean distance to their `nb_neighbors`
    /// nearest points is above the cloud's mean of that distance + `std_ratio` standard deviations.
    /// Returns the kept cloud and the kept indices (ascending).
    pub fn remove_statistical_outlier(&self, nb_neighbors: usize, std_ratio: f64) -> Result<(PointCloud, Vec<i32>)> {
        let nb = to_i32(nb_neighbors, "nb_neighbors")?;
        let mut cloud = None;
        let kept = self.indices(|idx, cap, n| {
            let mut out = ptr::null_mut();
            // SAFETY: valid handle; `idx` has room for `cap` ints; out-pointers valid.
            let status = unsafe {
                sys::o3d_pointcloud_remove_statistical_outlier(&mut out, idx, cap, n, self.as_raw(), nb, std_ratio)
            };
            cloud = NonNull::new(out);
            status
        })?;
        Ok((owned(cloud)?, kept))
    }

    /// Radius outlier removal: keep points with at least `nb_points` other points within `radius`.
    /// Returns the kept cloud and the kept indices (ascending).
    pub fn remove_radius_outlier(&self, nb_points: usize, radius: f64) -> Result<(PointCloud, Vec<i32>)> {
        let nb = to_i32(nb_points, "nb_points")?;
        let mut cloud = None;
        let kept = self.indices(|idx, cap, n| {
            let mut out = ptr::null_mut();
            // SAFETY: valid handle; `idx` has room for `cap` ints; out-pointers valid.
            let status =
                unsafe { sys::o3d_pointcloud_remove_radius_outlier(&mut out, idx, cap, n, self.as_raw(), nb, radius) };
            cloud = NonNull::new(out);
            status
        })?;
        Ok((owned(cloud)?, kept))
    }

    /// RANSAC plane fit: `(a, b, c, d)` with `a x + b y + c z + d = 0` and unit `(a, b, c)`, and
    /// the inlier indices (ascending). Same seed → same result on any thread count.
    pub fn segment_plane(
        &self,
        distance_threshold: f64,
        ransac_n: usize,
        num_iterations: usize,
        probability: f64,
        seed: u64,
    ) -> Result<([f64; 4], Vec<i32>)> {
        let ransac_n = to_i32(ransac_n, "ransac_n")?;
        let num_iterations = to_i32(num_iterations, "num_iterations")?;
        let mut plane = [0.0f64; 4];
        let inliers = self.indices(|idx, cap, n| {
            // SAFETY: valid handle; room for 4 doubles; `idx` has room for `cap` ints.
            unsafe {
                sys::o3d_pointcloud_segment_plane(
                    plane.as_mut_ptr(),
                    idx,
                    cap,
                    n,
                    self.as_raw(),
                    distance_threshold,
                    ransac_n,
                    num_iterations,
                    probability,
                    seed,
                )
            }
        })?;
        Ok((plane, inliers))
    }

    /// DBSCAN: one label per point, clusters `0, 1, ...` in order of their lowest point index,
    /// `-1` for noise.
    pub fn cluster_dbscan(&self, eps: f64, min_points: usize) -> Result<Vec<i32>> {
        let min_points = to_i32(min_points, "min_points")?;
        // SAFETY: `out` has room for `cap` ints or is NULL.
        copy_out::<i32>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_cluster_dbscan(out, cap, n, self.as_raw(), eps, min_points)
        })
    }

    /// Mean and covariance (row-major, divided by N) of the points. Empty cloud → Err.
    pub fn compute_mean_and_covariance(&self) -> Result<([f64; 3], [[f64; 3]; 3])> {
        let mut mean = [0.0f64; 3];
        let mut cov = [[0.0f64; 3]; 3];
        // SAFETY: room for 3 and 9 contiguous doubles.
        check(unsafe {
            sys::o3d_pointcloud_compute_mean_and_covariance(
                mean.as_mut_ptr(),
                cov.as_mut_ptr().cast::<f64>(),
                self.as_raw(),
            )
        })?;
        Ok((mean, cov))
    }

    /// Mahalanobis distance of each point to the cloud's distribution.
    pub fn compute_mahalanobis_distance(&self) -> Result<Vec<f64>> {
        // SAFETY: `out` has room for `cap` doubles or is NULL.
        copy_out::<f64>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_compute_mahalanobis_distance(out, cap, n, self.as_raw())
        })
    }
}

impl fmt::Debug for PointCloud {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("PointCloud")
            .field("points", &self.try_len().unwrap_or(0))
            .field("has_normals", &self.has_normals().unwrap_or(false))
            .field("has_colors", &self.has_colors().unwrap_or(false))
            .field("has_covariances", &self.has_covariances().unwrap_or(false))
            .finish()
    }
}
