//! `KDTreeFlann` (o3d.geometry.KDTreeFlann) with one-call batch searches, over 3-D points or over
//! points of any dimension (features).
use std::fmt;
use std::ptr;
use std::slice;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::feature::{rows_of, Feature};
use crate::pointcloud::{PointCloud, SearchParam};
use crate::util::{copy_out, handle, to_i32};

include!("generated/kdtree.rs");

handle! {
    /// A KD-tree over 3-D points, or over points of any dimension ([`KDTreeFlann::from_feature`],
    /// [`KDTreeFlann::from_points_xd`]). It copies the points, so it outlives what it was built from.
    /// `Send` and `Sync`: searches take the tree `const` and may run concurrently.
    KDTreeFlann(sys::o3d_kdtree_t, "tree"), new_tree, sys::o3d_kdtree_destroy
}

/// Flat result of a batch search: the neighbours of query `i` are
/// `indices[offsets[i]..offsets[i+1]]`, sorted by increasing distance, with squared distances in
/// `distances2` at the same positions.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SearchResult {
    /// `num_queries + 1` offsets into `indices` / `distances2`.
    pub offsets: Vec<i64>,
    /// Neighbour indices into the tree's points.
    pub indices: Vec<i32>,
    /// Squared distances to the neighbours.
    pub distances2: Vec<f64>,
}

impl SearchResult {
    /// Number of queries.
    pub fn num_queries(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// Neighbour indices and squared distances of query `i`.
    pub fn neighbors(&self, i: usize) -> (&[i32], &[f64]) {
        let (a, b) = (self.offsets[i] as usize, self.offsets[i + 1] as usize);
        (&self.indices[a..b], &self.distances2[a..b])
    }
}

handle! {
    /// A batch search result still owned by the library, read through zero-copy views (immutable
    /// after creation: `Send` and `Sync`).
    SearchResultRef(sys::o3d_search_result_t, "search result"), new_result, sys::o3d_search_result_destroy
}

impl SearchResultRef {
    /// (number of queries, total number of neighbours).
    pub fn counts(&self) -> Result<(usize, usize)> {
        let (mut q, mut t) = (0, 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_search_result_counts(&mut q, &mut t, self.raw.as_ptr()) })?;
        Ok((q, t))
    }

    /// Zero-copy (offsets, indices, squared distances), valid as long as `self`.
    pub fn view(&self) -> Result<(&[i64], &[i32], &[f64])> {
        let (q, t) = self.counts()?;
        let (mut o, mut i, mut d) = (ptr::null(), ptr::null(), ptr::null());
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_search_result_view(&mut o, &mut i, &mut d, self.raw.as_ptr()) })?;
        // SAFETY: the header promises q + 1 offsets and t indices / distances, valid until destroy.
        unsafe {
            let mk = |p: *const i64, n| if p.is_null() || n == 0 { &[][..] } else { slice::from_raw_parts(p, n) };
            let offsets = mk(o, q + 1);
            let indices = if i.is_null() || t == 0 { &[][..] } else { slice::from_raw_parts(i, t) };
            let dist = if d.is_null() || t == 0 { &[][..] } else { slice::from_raw_parts(d, t) };
            Ok((offsets, indices, dist))
        }
    }

    /// Copy into an owned [`SearchResult`] (`o3d_search_result_get_*`).
    pub fn to_search_result(&self) -> Result<SearchResult> {
        let raw = self.raw.as_ptr();
        // SAFETY: `out` has room for `cap` values, or is NULL for the count query.
        Ok(SearchResult {
            offsets: copy_out(|out, cap, n| unsafe { sys::o3d_search_result_get_offsets(out, cap, n, raw) })?,
            indices: copy_out(|out, cap, n| unsafe { sys::o3d_search_result_get_indices(out, cap, n, raw) })?,
            distances2: copy_out(|out, cap, n| unsafe { sys::o3d_search_result_get_distances2(out, cap, n, raw) })?,
        })
    }
}

impl fmt::Debug for SearchResultRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SearchResultRef").field("counts", &self.counts().ok()).finish()
    }
}

impl KDTreeFlann {
    /// Build a tree over `points` (copied). Non-finite coordinates → Err.
    pub fn from_points(points: &[[f64; 3]]) -> Result<KDTreeFlann> {
        // SAFETY: points.len() rows of 3 contiguous doubles.
        new_tree(|out| unsafe { sys::o3d_kdtree_create_from_points(out, points.as_ptr().cast(), points.len()) })
    }

    /// Build a tree over `data.len() / dimension` points of `dimension` values each, one after the
    /// other (copied). A length that is not whole points is an error.
    pub fn from_points_xd(data: &[f64], dimension: usize) -> Result<KDTreeFlann> {
        let n = rows_of(data.len(), dimension)?;
        // SAFETY: data holds n * dimension doubles.
        new_tree(|out| unsafe { sys::o3d_kdtree_create_from_points_xd(out, data.as_ptr(), dimension, n) })
    }

    /// Search `queries.len() / dimension` query points of `dimension` values each (which must be
    /// the tree's dimension) at once, on `num_threads` threads (0 = the library default), keeping
    /// the result in the library.
    pub fn search_xd_ref(
        &self,
        queries: &[f64],
        dimension: usize,
        param: SearchParam,
        num_threads: usize,
    ) -> Result<SearchResultRef> {
        let n = rows_of(queries.len(), dimension)?;
        let p = param.to_raw()?;
        let threads = to_i32(num_threads, "num_threads")?;
        // SAFETY: queries holds n * dimension doubles; valid parameter struct.
        new_result(|out| unsafe {
            sys::o3d_kdtree_search_xd(out, self.raw.as_ptr(), queries.as_ptr(), n, dimension, &p, threads)
        })
    }

    /// As [`Self::search_xd_ref`], copied into owned vectors (library-default thread count).
    pub fn search_xd(&self, queries: &[f64], dimension: usize, param: SearchParam) -> Result<SearchResult> {
        self.search_xd_ref(queries, dimension, param, 0)?.to_search_result()
    }

    /// Search with every descriptor of `feature` as a query.
    pub fn search_feature(&self, feature: &Feature, param: SearchParam) -> Result<SearchResult> {
        self.search_xd(feature.data(), feature.dimension(), param)
    }

    /// One query of any dimension (Open3D `search_vector_xd`): (indices, squared distances).
    pub fn search_vector_xd(&self, query: &[f64], param: SearchParam) -> Result<(Vec<i32>, Vec<f64>)> {
        let r = self.search_xd(query, query.len(), param)?;
        Ok((r.indices, r.distances2))
    }

    /// The `knn` nearest points of `query` (Open3D `search_knn_vector_xd`).
    pub fn search_knn_vector_xd(&self, query: &[f64], knn: usize) -> Result<(Vec<i32>, Vec<f64>)> {
        self.search_vector_xd(query, SearchParam::Knn { knn })
    }

    /// All points within `radius` of `query` (Open3D `search_radius_vector_xd`).
    pub fn search_radius_vector_xd(&self, query: &[f64], radius: f64) -> Result<(Vec<i32>, Vec<f64>)> {
        self.search_vector_xd(query, SearchParam::Radius { radius })
    }

    /// At most `max_nn` nearest points within `radius` (Open3D `search_hybrid_vector_xd`).
    pub fn search_hybrid_vector_xd(&self, query: &[f64], radius: f64, max_nn: usize) -> Result<(Vec<i32>, Vec<f64>)> {
        self.search_vector_xd(query, SearchParam::Hybrid { radius, max_nn })
    }

    /// True when the tree indexes no points.
    pub fn is_empty(&self) -> Result<bool> {
        Ok(self.len()? == 0)
    }

    /// Search every row of `queries` at once (in parallel), keeping the result in the library.
    pub fn search_ref(&self, queries: &[[f64; 3]], param: SearchParam) -> Result<SearchResultRef> {
        let p = param.to_raw()?;
        // SAFETY: queries.len() rows of 3 doubles; valid parameter struct.
        new_result(|out| unsafe {
            sys::o3d_kdtree_search(out, self.raw.as_ptr(), queries.as_ptr().cast(), queries.len(), &p, 0)
        })
    }

    /// As [`Self::search_ref`] with float32 queries.
    pub fn search_ref_f32(&self, queries: &[[f32; 3]], param: SearchParam) -> Result<SearchResultRef> {
        let p = param.to_raw()?;
        // SAFETY: queries.len() rows of 3 floats; valid parameter struct.
        new_result(|out| unsafe {
            sys::o3d_kdtree_search_f32(out, self.raw.as_ptr(), queries.as_ptr().cast(), queries.len(), &p, 0)
        })
    }

    /// Search every row of `queries` at once; the result is copied into owned vectors.
    pub fn search(&self, queries: &[[f64; 3]], param: SearchParam) -> Result<SearchResult> {
        self.search_ref(queries, param)?.to_search_result()
    }

    /// As [`Self::search`] with float32 queries.
    pub fn search_f32(&self, queries: &[[f32; 3]], param: SearchParam) -> Result<SearchResult> {
        self.search_ref_f32(queries, param)?.to_search_result()
    }

    /// One query (Open3D `search_vector_3d`): (indices, squared distances), nearest first.
    pub fn search_vector_3d(&self, query: [f64; 3], param: SearchParam) -> Result<(Vec<i32>, Vec<f64>)> {
        let r = self.search(&[query], param)?;
        Ok((r.indices, r.distances2))
    }

    /// The `knn` nearest points of `query` (Open3D `search_knn_vector_3d`).
    pub fn search_knn_vector_3d(&self, query: [f64; 3], knn: usize) -> Result<(Vec<i32>, Vec<f64>)> {
        self.search_vector_3d(query, SearchParam::Knn { knn })
    }

    /// All points within `radius` of `query` (Open3D `search_radius_vector_3d`).
    pub fn search_radius_vector_3d(&self, query: [f64; 3], radius: f64) -> Result<(Vec<i32>, Vec<f64>)> {
        self.search_vector_3d(query, SearchParam::Radius { radius })
    }

    /// At most `max_nn` nearest points within `radius` (Open3D `search_hybrid_vector_3d`).
    pub fn search_hybrid_vector_3d(&self, query: [f64; 3], radius: f64, max_nn: usize) -> Result<(Vec<i32>, Vec<f64>)> {
        self.search_vector_3d(query, SearchParam::Hybrid { radius, max_nn })
    }
}

impl fmt::Debug for KDTreeFlann {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("KDTreeFlann").field("len", &self.len().ok()).finish()
    }
}
