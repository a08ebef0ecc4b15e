//! `TriangleMesh` operations: normals, transforms, clean-up, topology queries and processing.
use o3d_sys as sys;

use crate::error::{check, Result};
use crate::pointcloud::{new_cloud, PointCloud};
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::{c_enum, mat4_ptr, opt_ptr, to_i32};

include!("generated/trianglemesh_ops.rs");

/// Edge-connected triangle clusters ([`TriangleMesh::cluster_connected_triangles`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TriangleClusters {
    /// Each triangle's cluster, clusters numbered by their lowest triangle index.
    pub triangle_clusters: Vec<i32>,
    /// Triangles per cluster.
    pub cluster_n_triangles: Vec<i32>,
    /// Surface area per cluster.
    pub cluster_area: Vec<f64>,
}

type FlagFn = unsafe extern "C" fn(*mut i32, *const sys::o3d_trianglemesh_t) -> sys::o3d_status;
type Vec3Fn = unsafe extern "C" fn(*mut f64, *const sys::o3d_trianglemesh_t) -> sys::o3d_status;

impl TriangleMesh {
    fn flag(&self, f: FlagFn) -> Result<bool> {
        let mut v = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { f(&mut v, self.as_raw()) })?;
        Ok(v != 0)
    }

    fn vec3(&self, f: Vec3Fn) -> Result<[f64; 3]> {
        let mut out = [0.0; 3];
        // SAFETY: room for 3 doubles.
        check(unsafe { f(out.as_mut_ptr(), self.as_raw()) })?;
        Ok(out)
    }

    // ---- normals, colors, transforms, bounds ----

    /// Apply a row-major 4x4 transform (normals rotated).
    pub fn transform(&mut self, transformation: &[[f64; 4]; 4]) -> Result<&mut Self> {
        // SAFETY: 16 contiguous doubles.
        check(unsafe { sys::o3d_trianglemesh_transform(self.raw_mut(), mat4_ptr(transformation)) })?;
        Ok(self)
    }

    /// Rotate by the row-major 3x3 `rotation` about `center` (`None`: the mesh's center).
    pub fn rotate(&mut self, rotation: &[[f64; 3]; 3], center: Option<[f64; 3]>) -> Result<&mut Self> {
        // SAFETY: 9 contiguous doubles; center NULL or 3 doubles.
        check(unsafe { sys::o3d_trianglemesh_rotate(self.raw_mut(), rotation.as_ptr().cast(), opt_ptr(&center)) })?;
        Ok(self)
    }

    /// Scale about `center` (`None`: the mesh's center).
    pub fn scale(&mut self, scale: f64, center: Option<[f64; 3]>) -> Result<&mut Self> {
        // SAFETY: center NULL or 3 doubles.
        check(unsafe { sys::o3d_trianglemesh_scale(self.raw_mut(), scale, opt_ptr(&center)) })?;
        Ok(self)
    }

    /// Component-wise minimum of the vertices ((0,0,0) when empty).
    pub fn get_min_bound(&self) -> Result<[f64; 3]> {
        self.vec3(sys::o3d_trianglemesh_get_min_bound)
    }

    /// Component-wise maximum of the vertices ((0,0,0) when empty).
    pub fn get_max_bound(&self) -> Result<[f64; 3]> {
        self.vec3(sys::o3d_trianglemesh_get_max_bound)
    }

    /// Mean of the vertices ((0,0,0) when empty).
    pub fn get_center(&self) -> Result<[f64; 3]> {
        self.vec3(sys::o3d_trianglemesh_get_center)
    }

    /// Axis-aligned bounding box as (min corner, max corner).
    pub fn get_axis_aligned_bounding_box(&self) -> Result<([f64; 3], [f64; 3])> {
        let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
        // SAFETY: room for 3 + 3 doubles.
        check(unsafe {
            sys::o3d_trianglemesh_get_axis_aligned_bounding_box(lo.as_mut_ptr(), hi.as_mut_ptr(), self.as_raw())
        })?;
        Ok((lo, hi))
    }

    // ---- clean-up (in place) ----

    // ---- queries ----

    /// Sum of the triangle areas.
    pub fn get_surface_area(&self) -> Result<f64> {
        let mut v = 0.0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_get_surface_area(&mut v, self.as_raw()) })?;
        Ok(v)
    }

    /// Enclosed volume (not watertight and orientable → Err).
    pub fn get_volume(&self) -> Result<f64> {
        let mut v = 0.0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_get_volume(&mut v, self.as_raw()) })?;
        Ok(v)
    }

    /// Edge- and vertex-manifold, no boundary, not self-intersecting.
    pub fn is_watertight(&self) -> Result<bool> {
        self.flag(sys::o3d_trianglemesh_is_watertight)
    }

    /// Every edge in one or two triangles (only two unless `allow_boundary_edges`).
    pub fn is_edge_manifold(&self, allow_boundary_edges: bool) -> Result<bool> {
        let mut v = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_is_edge_manifold(&mut v, self.as_raw(), allow_boundary_edges as i32) })?;
        Ok(v != 0)
    }

    /// The triangles around every vertex form one fan.
    pub fn is_vertex_manifold(&self) -> Result<bool> {
        self.flag(sys::o3d_trianglemesh_is_vertex_manifold)
    }

    /// Some two triangles sharing no vertex intersect.
    pub fn is_self_intersecting(&self) -> Result<bool> {
        self.flag(sys::o3d_trianglemesh_is_self_intersecting)
    }

    /// The triangles can be oriented consistently.
    pub fn is_orientable(&self) -> Result<bool> {
        self.flag(sys::o3d_trianglemesh_is_orientable)
    }

    /// V - E + F.
    pub fn euler_poincare_characteristic(&self) -> Result<i64> {
        let mut v = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_euler_poincare_characteristic(&mut v, self.as_raw()) })?;
        Ok(v)
    }

    /// Edge-connected components of the triangles.
    pub fn cluster_connected_triangles(&self) -> Result<TriangleClusters> {
        let cap = self.num_triangles()?;
        let mut out = TriangleClusters {
            triangle_clusters: vec![0; cap],
            cluster_n_triangles: vec![0; cap],
            cluster_area: vec![0.0; cap],
        };
        let (mut n_tri, mut n_clusters) = (0usize, 0usize);
        // SAFETY: three buffers of `cap` values each.
        check(unsafe {
            sys::o3d_trianglemesh_cluster_connected_triangles(
                out.triangle_clusters.as_mut_ptr(),
                out.cluster_n_triangles.as_mut_ptr(),
                out.cluster_area.as_mut_ptr(),
                cap,
                &mut n_tri,
                &mut n_clusters,
                self.as_raw(),
            )
        })?;
        out.triangle_clusters.truncate(n_tri.min(cap));
        out.cluster_n_triangles.truncate(n_clusters.min(cap));
        out.cluster_area.truncate(n_clusters.min(cap));
        Ok(out)
    }

    // ---- processing (new mesh or cloud) ----

    /// `number_of_points` area-weighted uniform samples; same seed → same cloud.
    pub fn sample_points_uniformly(
        &self,
        number_of_points: usize,
        use_triangle_normal: bool,
        seed: u64,
    ) -> Result<PointCloud> {
        // SAFETY: valid handle and out-pointer.
        new_cloud(|out| unsafe {
            sys::o3d_trianglemesh_sample_points_uniformly(
                out,
                self.as_raw(),
                number_of_points,
                use_triangle_normal as i32,
                seed,
            )
        })
    }

    /// Poisson-disk samples by sample elimination from `init_factor * number_of_points` (Open3D: 5).
    pub fn sample_points_poisson_disk(
        &self,
        number_of_points: usize,
        init_factor: f64,
        use_triangle_normal: bool,
        seed: u64,
    ) -> Result<PointCloud> {
        // SAFETY: valid handle and out-pointer.
        new_cloud(|out| unsafe {
            sys::o3d_trianglemesh_sample_points_poisson_disk(
                out,
                self.as_raw(),
                number_of_points,
                init_factor,
                use_triangle_normal as i32,
                seed,
            )
        })
    }

    /// Vertex clustering on a voxel grid of edge `voxel_size`.
    pub fn simplify_vertex_clustering(
        &self,
        voxel_size: f64,
        contraction: SimplificationContraction,
    ) -> Result<TriangleMesh> {
        let raw = contraction.raw();
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_simplify_vertex_clustering(out, self.as_raw(), voxel_size, raw) })
    }

    /// Quadric edge-collapse decimation (`maximum_error` `f64::INFINITY`: no limit; Open3D's
    /// `boundary_weight` default 1).
    pub fn simplify_quadric_decimation(
        &self,
        target_number_of_triangles: usize,
        maximum_error: f64,
        boundary_weight: f64,
    ) -> Result<TriangleMesh> {
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_simplify_quadric_decimation(
                out,
                self.as_raw(),
                target_number_of_triangles,
                maximum_error,
                boundary_weight,
            )
        })
    }

    /// Average of each vertex and its neighbours, `iterations` times.
    pub fn filter_smooth_simple(&self, iterations: usize, scope: FilterScope) -> Result<TriangleMesh> {
        let n = to_i32(iterations, "number_of_iterations")?;
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_filter_smooth_simple(out, self.as_raw(), n, scope.raw()) })
    }

    /// Laplacian smoothing (Open3D default lambda 0.5).
    pub fn filter_smooth_laplacian(&self, iterations: usize, lambda: f64, scope: FilterScope) -> Result<TriangleMesh> {
        let n = to_i32(iterations, "number_of_iterations")?;
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_filter_smooth_laplacian(out, self.as_raw(), n, lambda, scope.raw())
        })
    }

    /// Taubin smoothing (Open3D defaults lambda 0.5, mu -0.53).
    pub fn filter_smooth_taubin(
        &self,
        iterations: usize,
        lambda: f64,
        mu: f64,
        scope: FilterScope,
    ) -> Result<TriangleMesh> {
        let n = to_i32(iterations, "number_of_iterations")?;
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_filter_smooth_taubin(out, self.as_raw(), n, lambda, mu, scope.raw())
        })
    }

    /// Split every triangle into four at its edge midpoints, `iterations` times.
    pub fn subdivide_midpoint(&self, iterations: usize) -> Result<TriangleMesh> {
        let n = to_i32(iterations, "number_of_iterations")?;
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_subdivide_midpoint(out, self.as_raw(), n) })
    }

    /// Loop subdivision, `iterations` times.
    pub fn subdivide_loop(&self, iterations: usize) -> Result<TriangleMesh> {
        let n = to_i32(iterations, "number_of_iterations")?;
        // SAFETY: valid handle and out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_subdivide_loop(out, self.as_raw(), n) })
    }

    /// Triangles whose three vertices lie in the box (unused vertices dropped).
    pub fn crop_aabb(&self, min_bound: [f64; 3], max_bound: [f64; 3]) -> Result<TriangleMesh> {
        // SAFETY: 3 + 3 doubles.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_crop_aabb(out, self.as_raw(), min_bound.as_ptr(), max_bound.as_ptr())
        })
    }
}
