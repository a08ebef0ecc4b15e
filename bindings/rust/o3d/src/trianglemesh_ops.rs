//! `TriangleMesh` operations: normals, transforms, clean-up, topology queries and processing (the ones that are
//! one C call are generated: generated/trianglemesh_ops.rs).
use o3d_sys as sys;

use crate::error::{check, Result};
use crate::image::Image;
use crate::pointcloud::PointCloud;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::{c_enum, to_i32};

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

impl TriangleMesh {
    /// Axis-aligned bounding box as (min corner, max corner).
    pub fn get_axis_aligned_bounding_box(&self) -> Result<([f64; 3], [f64; 3])> {
        let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
        // SAFETY: room for 3 + 3 doubles.
        check(unsafe {
            sys::o3d_trianglemesh_get_axis_aligned_bounding_box(lo.as_mut_ptr(), hi.as_mut_ptr(), self.as_raw())
        })?;
        Ok((lo, hi))
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
}
