//! `TriangleMesh` operations: normals, transforms, clean-up, topology queries and processing (the ones that are
//! one C call are generated: generated/trianglemesh_ops.rs).
use o3d_sys as sys;

use crate::error::{check, Result};
use crate::image::Image;
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::c_enum;

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
}
