//! `TriangleMesh` (o3d.geometry.TriangleMesh): the container, its arrays and textures.
//! Normals, clean-up, queries and processing are in `trianglemesh_ops.rs`, primitives in
//! `trianglemesh_primitives.rs`.
use std::fmt;

use o3d_sys as sys;

use crate::array::{impl_arrays, Family};
use crate::error::Result;
use crate::image::Image;
use crate::util::{c_enum, handle};

include!("generated/trianglemesh.rs");

handle! {
    /// A triangle mesh: vertices (with optional normals and colors), triangles (with optional normals,
    /// per-corner UVs and material ids) and texture images.
    ///
    /// Owns an `o3d_trianglemesh_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and
    /// every mutation takes `&mut self`, so borrowed views can never outlive a mutation.
    TriangleMesh(sys::o3d_trianglemesh_t, "mesh"), new_mesh, sys::o3d_trianglemesh_destroy, sys::o3d_trianglemesh_clone
}
impl_arrays!(TriangleMesh, sys::o3d_trianglemesh_t);

/// The float64 arrays (`O3D_MESH_VERTICES` ... `O3D_MESH_TRIANGLE_UVS`).
const ARRAYS: Family<sys::o3d_trianglemesh_t, f64> = Family {
    has: sys::o3d_trianglemesh_has_array,
    shape: sys::o3d_trianglemesh_array_shape,
    set: sys::o3d_trianglemesh_set_array,
    get: sys::o3d_trianglemesh_get_array,
    view: sys::o3d_trianglemesh_array_view,
    view_mut: sys::o3d_trianglemesh_array_mutable_view,
    set_f32: Some(sys::o3d_trianglemesh_set_array_f32),
};
/// The int32 arrays (`O3D_MESH_TRIANGLES`, `O3D_MESH_TRIANGLE_MATERIAL_IDS`).
const INDICES: Family<sys::o3d_trianglemesh_t, i32> = Family {
    has: sys::o3d_trianglemesh_has_array,
    shape: sys::o3d_trianglemesh_array_shape,
    set: sys::o3d_trianglemesh_set_index_array,
    get: sys::o3d_trianglemesh_get_index_array,
    view: sys::o3d_trianglemesh_index_array_view,
    view_mut: sys::o3d_trianglemesh_index_array_mutable_view,
    set_f32: None,
};

impl TriangleMesh {
    /// A new empty mesh.
    pub fn new() -> Result<TriangleMesh> {
        // SAFETY: out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_create(out) })
    }

    /// A mesh holding `vertices` and `triangles` (indices are checked by every later operation).
    pub fn from_vertices_and_triangles(vertices: &[[f64; 3]], triangles: &[[i32; 3]]) -> Result<TriangleMesh> {
        let mut mesh = TriangleMesh::new()?;
        mesh.set_vertices(vertices)?;
        mesh.set_triangles(triangles)?;
        Ok(mesh)
    }

    fn has(&self, which: i32) -> Result<bool> {
        ARRAYS.has(self, which)
    }

    /// True if the array is present with the right row count (Open3D's `has_*`).
    pub fn has_array(&self, which: MeshArray) -> Result<bool> {
        self.has(which.raw())
    }

    /// True if there are vertices.
    pub fn has_vertices(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_VERTICES)
    }

    /// True if there are triangles.
    pub fn has_triangles(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_TRIANGLES)
    }

    /// True if there is one normal per vertex.
    pub fn has_vertex_normals(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_VERTEX_NORMALS)
    }

    /// True if there is one color per vertex.
    pub fn has_vertex_colors(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_VERTEX_COLORS)
    }

    /// True if there is one normal per triangle.
    pub fn has_triangle_normals(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_TRIANGLE_NORMALS)
    }

    /// True if there are three UVs per triangle.
    pub fn has_triangle_uvs(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_TRIANGLE_UVS)
    }

    /// True if there is one material id per triangle.
    pub fn has_triangle_material_ids(&self) -> Result<bool> {
        self.has(sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)
    }

    // ---- float64 arrays ----

    /// Replace a three-column array (copied once).
    pub fn set_array(&mut self, which: MeshArray, rows: &[[f64; 3]]) -> Result<()> {
        ARRAYS.set(self, which.raw(), rows)
    }

    /// Replace a three-column array from float32 input (converted in the single copy).
    pub fn set_array_f32(&mut self, which: MeshArray, rows: &[[f32; 3]]) -> Result<()> {
        ARRAYS.set_f32(self, which.raw(), rows)
    }

    /// Zero-copy view of a three-column array (empty when absent).
    pub fn array(&self, which: MeshArray) -> Result<&[[f64; 3]]> {
        ARRAYS.view(self, which.raw())
    }

    /// Writable zero-copy view of a three-column array.
    pub fn array_mut(&mut self, which: MeshArray) -> Result<&mut [[f64; 3]]> {
        ARRAYS.view_mut(self, which.raw())
    }

    /// Copy of a three-column array (`o3d_trianglemesh_get_array`).
    pub fn array_to_vec(&self, which: MeshArray) -> Result<Vec<[f64; 3]>> {
        ARRAYS.to_vec(self, which.raw())
    }

    /// Replace the vertices.
    pub fn set_vertices(&mut self, vertices: &[[f64; 3]]) -> Result<()> {
        self.set_array(MeshArray::Vertices, vertices)
    }

    /// Replace the vertex normals.
    pub fn set_vertex_normals(&mut self, normals: &[[f64; 3]]) -> Result<()> {
        self.set_array(MeshArray::VertexNormals, normals)
    }

    /// Replace the vertex colors.
    pub fn set_vertex_colors(&mut self, colors: &[[f64; 3]]) -> Result<()> {
        self.set_array(MeshArray::VertexColors, colors)
    }

    /// Replace the triangle normals.
    pub fn set_triangle_normals(&mut self, normals: &[[f64; 3]]) -> Result<()> {
        self.set_array(MeshArray::TriangleNormals, normals)
    }

    /// Zero-copy view of the vertices.
    pub fn vertices(&self) -> Result<&[[f64; 3]]> {
        self.array(MeshArray::Vertices)
    }

    /// Zero-copy view of the vertex normals.
    pub fn vertex_normals(&self) -> Result<&[[f64; 3]]> {
        self.array(MeshArray::VertexNormals)
    }

    /// Zero-copy view of the vertex colors.
    pub fn vertex_colors(&self) -> Result<&[[f64; 3]]> {
        self.array(MeshArray::VertexColors)
    }

    /// Zero-copy view of the triangle normals.
    pub fn triangle_normals(&self) -> Result<&[[f64; 3]]> {
        self.array(MeshArray::TriangleNormals)
    }

    /// Writable view of the vertices.
    pub fn vertices_mut(&mut self) -> Result<&mut [[f64; 3]]> {
        self.array_mut(MeshArray::Vertices)
    }

    /// Replace the per-corner UVs (three rows per triangle).
    pub fn set_triangle_uvs(&mut self, uvs: &[[f64; 2]]) -> Result<()> {
        ARRAYS.set(self, sys::O3D_MESH_TRIANGLE_UVS, uvs)
    }

    /// Zero-copy view of the per-corner UVs.
    pub fn triangle_uvs(&self) -> Result<&[[f64; 2]]> {
        ARRAYS.view(self, sys::O3D_MESH_TRIANGLE_UVS)
    }

    /// Writable view of the per-corner UVs.
    pub fn triangle_uvs_mut(&mut self) -> Result<&mut [[f64; 2]]> {
        ARRAYS.view_mut(self, sys::O3D_MESH_TRIANGLE_UVS)
    }

    /// Copy of the per-corner UVs.
    pub fn triangle_uvs_to_vec(&self) -> Result<Vec<[f64; 2]>> {
        ARRAYS.to_vec(self, sys::O3D_MESH_TRIANGLE_UVS)
    }

    // ---- int32 arrays ----

    /// Replace the triangles (vertex indices).
    pub fn set_triangles(&mut self, triangles: &[[i32; 3]]) -> Result<()> {
        INDICES.set(self, sys::O3D_MESH_TRIANGLES, triangles)
    }

    /// Zero-copy view of the triangles.
    pub fn triangles(&self) -> Result<&[[i32; 3]]> {
        INDICES.view(self, sys::O3D_MESH_TRIANGLES)
    }

    /// Writable view of the triangles (indices are re-checked by every operation).
    pub fn triangles_mut(&mut self) -> Result<&mut [[i32; 3]]> {
        INDICES.view_mut(self, sys::O3D_MESH_TRIANGLES)
    }

    /// Copy of the triangles.
    pub fn triangles_to_vec(&self) -> Result<Vec<[i32; 3]>> {
        INDICES.to_vec(self, sys::O3D_MESH_TRIANGLES)
    }

    /// Replace the per-triangle material ids.
    pub fn set_triangle_material_ids(&mut self, ids: &[i32]) -> Result<()> {
        INDICES.set(self, sys::O3D_MESH_TRIANGLE_MATERIAL_IDS, ids)
    }

    /// Zero-copy view of the per-triangle material ids.
    pub fn triangle_material_ids(&self) -> Result<&[i32]> {
        INDICES.view(self, sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)
    }

    /// Writable view of the per-triangle material ids.
    pub fn triangle_material_ids_mut(&mut self) -> Result<&mut [i32]> {
        INDICES.view_mut(self, sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)
    }

    /// Copy of the per-triangle material ids.
    pub fn triangle_material_ids_to_vec(&self) -> Result<Vec<i32>> {
        INDICES.to_vec(self, sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)
    }

    // ---- textures ----

    /// Copies of every texture.
    pub fn textures(&self) -> Result<Vec<Image>> {
        (0..self.texture_count()?).map(|i| self.texture(i)).collect()
    }
}

impl fmt::Debug for TriangleMesh {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TriangleMesh")
            .field("vertices", &self.num_vertices().unwrap_or(0))
            .field("triangles", &self.num_triangles().unwrap_or(0))
            .finish()
    }
}
