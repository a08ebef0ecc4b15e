//! `TriangleMesh` operations: normals, transforms, clean-up, topology queries and processing (the ones that are
//! one C call are generated: generated/trianglemesh_ops.rs).
use o3d_sys as sys;

use crate::error::{check, Result};
use crate::image::Image;
use crate::pointcloud::PointCloud;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::{c_enum, copy_out, index, index_lists, to_i32};

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

/// Index pairs as `usize`s (each documented non-negative).
fn pairs(raw: Vec<[i32; 2]>) -> Result<Vec<[usize; 2]>> {
    raw.into_iter().map(|[a, b]| Ok([index(a)?, index(b)?])).collect()
}

impl TriangleMesh {
    /// The vertex adjacency list (Open3D's `compute_adjacency_list`, returned rather than stored):
    /// per vertex, the vertices joined to it by a triangle side, ascending (empty for an unused vertex).
    pub fn compute_adjacency_list(&self) -> Result<Vec<Vec<usize>>> {
        // SAFETY: valid handle; out-pointer.
        index_lists(|out| unsafe { sys::o3d_trianglemesh_compute_adjacency_list(out, self.as_raw()) })
    }

    /// Edges (min, max vertex index; ascending) of more than two triangles, and of one unless
    /// `allow_boundary_edges` (Open3D's default `true`).
    pub fn get_non_manifold_edges(&self, allow_boundary_edges: bool) -> Result<Vec<[usize; 2]>> {
        // SAFETY: `out` has room for `cap` pairs of ints or is NULL.
        pairs(copy_out::<[i32; 2]>(|out, cap, n| unsafe {
            sys::o3d_trianglemesh_get_non_manifold_edges(
                out.cast(),
                cap,
                n,
                self.as_raw(),
                i32::from(allow_boundary_edges),
            )
        })?)
    }

    /// Vertices whose triangles do not form one fan (ascending).
    pub fn get_non_manifold_vertices(&self) -> Result<Vec<usize>> {
        // SAFETY: `out` has room for `cap` ints or is NULL.
        copy_out::<i32>(|out, cap, n| unsafe {
            sys::o3d_trianglemesh_get_non_manifold_vertices(out, cap, n, self.as_raw())
        })?
        .into_iter()
        .map(index)
        .collect()
    }

    /// Pairs (i < j, ascending) of triangles that share no vertex and intersect.
    pub fn get_self_intersecting_triangles(&self) -> Result<Vec<[usize; 2]>> {
        // SAFETY: `out` has room for `cap` pairs of ints or is NULL.
        pairs(copy_out::<[i32; 2]>(|out, cap, n| unsafe {
            sys::o3d_trianglemesh_get_self_intersecting_triangles(out.cast(), cap, n, self.as_raw())
        })?)
    }

    /// As-rigid-as-possible deformation (Sorkine & Alexa 2007; Open3D's
    /// `deform_as_rigid_as_possible`): the constrained vertices moved to their positions (one per
    /// index), the others so that every one-ring turns as rigidly as it can, `max_iter` alternations.
    /// The new mesh holds vertices and triangles only. Open3D's defaults: `Spokes`, `smoothed_alpha` 0.01.
    pub fn deform_as_rigid_as_possible(
        &self,
        constraint_vertex_indices: &[usize],
        constraint_vertex_positions: &[[f64; 3]],
        max_iter: usize,
        energy: DeformAsRigidAsPossibleEnergy,
        smoothed_alpha: f64,
    ) -> Result<TriangleMesh> {
        let ids = constraint_vertex_indices
            .iter()
            .map(|&i| to_i32(i, "constraint vertex index"))
            .collect::<Result<Vec<i32>>>()?;
        let max_iter = to_i32(max_iter, "max_iter")?;
        // SAFETY: valid handle; `ids.len()` ints; `constraint_vertex_positions.len()` rows of 3 contiguous doubles.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_deform_as_rigid_as_possible(
                out,
                self.as_raw(),
                ids.as_ptr(),
                ids.len(),
                constraint_vertex_positions.as_ptr().cast(),
                constraint_vertex_positions.len(),
                max_iter,
                energy.raw(),
                smoothed_alpha,
            )
        })
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
