//! `HalfEdgeTriangleMesh` (o3d.geometry.HalfEdgeTriangleMesh): a cleaned, manifold copy of a triangle
//! mesh with its half-edges, for walking one-rings and boundary loops. It never changes once made;
//! its arrays are copied out.
use std::fmt;

use o3d_sys as sys;

use crate::error::Result;
use crate::trianglemesh::TriangleMesh;
use crate::util::{copy_out, handle, index, index_lists, to_i32};

handle! {
    /// Vertices, triangles and their half-edges: half-edge `3 t + k` is side k of triangle t, from
    /// `triangles[t][k]` to `triangles[t][(k + 1) % 3]`.
    ///
    /// Owns an `o3d_halfedgemesh_t`. `Send` and `Sync`: it never changes after it is made.
    HalfEdgeTriangleMesh(sys::o3d_halfedgemesh_t, "half-edge mesh"), new_halfedgemesh, sys::o3d_halfedgemesh_destroy
}

/// One half-edge (o3d.geometry.HalfEdge).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct HalfEdge {
    /// The next half-edge of the same triangle.
    pub next: usize,
    /// The opposite half-edge; `None` on a boundary.
    pub twin: Option<usize>,
    /// From and to vertex.
    pub vertex_indices: [usize; 2],
    /// The triangle it belongs to.
    pub triangle_index: usize,
}

impl HalfEdge {
    /// Whether it lies on a boundary (has no twin).
    pub fn is_boundary(&self) -> bool {
        self.twin.is_none()
    }
}

impl HalfEdgeTriangleMesh {
    /// Open3D's `create_from_triangle_mesh`: the mesh cleaned first (equal vertices merged, duplicated
    /// and degenerate triangles and unreferenced vertices dropped), normals computed afresh, colors
    /// kept. A non-manifold mesh is an `InvalidArgument` error.
    pub fn create_from_triangle_mesh(mesh: &TriangleMesh) -> Result<HalfEdgeTriangleMesh> {
        // SAFETY: valid handle; out-pointer.
        new_halfedgemesh(|out| unsafe { sys::o3d_halfedgemesh_create_from_triangle_mesh(out, mesh.as_raw()) })
    }

    fn array(&self, which: i32) -> Result<Vec<[f64; 3]>> {
        // SAFETY: `out` has room for `cap` rows of 3 doubles or is NULL.
        copy_out::<[f64; 3]>(|out, cap, n| unsafe {
            sys::o3d_halfedgemesh_get_array(out.cast(), cap, n, self.as_raw(), which)
        })
    }

    /// Copy of the vertex positions.
    pub fn vertices(&self) -> Result<Vec<[f64; 3]>> {
        self.array(sys::O3D_HALFEDGEMESH_VERTICES)
    }

    /// Copy of the unit, area-weighted vertex normals.
    pub fn vertex_normals(&self) -> Result<Vec<[f64; 3]>> {
        self.array(sys::O3D_HALFEDGEMESH_VERTEX_NORMALS)
    }

    /// Copy of the vertex colors (empty when the mesh had none).
    pub fn vertex_colors(&self) -> Result<Vec<[f64; 3]>> {
        self.array(sys::O3D_HALFEDGEMESH_VERTEX_COLORS)
    }

    /// Copy of the unit triangle normals.
    pub fn triangle_normals(&self) -> Result<Vec<[f64; 3]>> {
        self.array(sys::O3D_HALFEDGEMESH_TRIANGLE_NORMALS)
    }

    /// Copy of the triangles (vertex indices).
    pub fn triangles(&self) -> Result<Vec<[i32; 3]>> {
        // SAFETY: `out` has room for `cap` rows of 3 ints or is NULL.
        copy_out::<[i32; 3]>(|out, cap, n| unsafe {
            sys::o3d_halfedgemesh_get_triangles(out.cast(), cap, n, self.as_raw())
        })
    }

    /// The half-edges, half-edge `3 t + k` being side k of triangle t.
    pub fn half_edges(&self) -> Result<Vec<HalfEdge>> {
        // SAFETY: `out` has room for `cap` rows of 5 ints or is NULL.
        let rows = copy_out::<[i32; 5]>(|out, cap, n| unsafe {
            sys::o3d_halfedgemesh_get_half_edges(out.cast(), cap, n, self.as_raw())
        })?;
        rows.into_iter()
            .map(|[next, twin, from, to, triangle]| {
                Ok(HalfEdge {
                    next: index(next)?,
                    twin: usize::try_from(twin).ok(),
                    vertex_indices: [index(from)?, index(to)?],
                    triangle_index: index(triangle)?,
                })
            })
            .collect()
    }

    /// Per vertex, its outgoing half-edges in fan order (from its boundary half-edge when it has one,
    /// else from its lowest-numbered one).
    pub fn ordered_half_edge_from_vertex(&self) -> Result<Vec<Vec<usize>>> {
        // SAFETY: valid handle; out-pointer.
        index_lists(|out| unsafe { sys::o3d_halfedgemesh_get_ordered_half_edge_from_vertex(out, self.as_raw()) })
    }

    /// The boundary loop through `vertex_index` as half-edge indices, along the half-edges' direction
    /// (empty when the vertex is not on a boundary; a vertex out of range is an error).
    pub fn boundary_half_edges_from_vertex(&self, vertex_index: usize) -> Result<Vec<usize>> {
        let v = to_i32(vertex_index, "vertex_index")?;
        // SAFETY: `out` has room for `cap` ints or is NULL.
        copy_out::<i32>(|out, cap, n| unsafe {
            sys::o3d_halfedgemesh_boundary_half_edges_from_vertex(out, cap, n, self.as_raw(), v)
        })?
        .into_iter()
        .map(index)
        .collect()
    }

    /// The same loop as vertex indices, starting with `vertex_index`.
    pub fn boundary_vertices_from_vertex(&self, vertex_index: usize) -> Result<Vec<usize>> {
        let v = to_i32(vertex_index, "vertex_index")?;
        // SAFETY: `out` has room for `cap` ints or is NULL.
        copy_out::<i32>(|out, cap, n| unsafe {
            sys::o3d_halfedgemesh_boundary_vertices_from_vertex(out, cap, n, self.as_raw(), v)
        })?
        .into_iter()
        .map(index)
        .collect()
    }

    /// Every boundary loop once, as vertex indices (loops start at their lowest vertex).
    pub fn get_boundaries(&self) -> Result<Vec<Vec<usize>>> {
        // SAFETY: valid handle; out-pointer.
        index_lists(|out| unsafe { sys::o3d_halfedgemesh_get_boundaries(out, self.as_raw()) })
    }
}

impl fmt::Debug for HalfEdgeTriangleMesh {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let count = |r: Result<usize>| r.map_or_else(|_| "?".to_string(), |n| n.to_string());
        f.debug_struct("HalfEdgeTriangleMesh")
            .field("vertices", &count(self.vertices().map(|v| v.len())))
            .field("triangles", &count(self.triangles().map(|t| t.len())))
            .finish()
    }
}
