//! `TriangleMesh` (o3d.geometry.TriangleMesh): the container, its arrays and textures.
//! Normals, clean-up, queries and processing are in `trianglemesh_ops.rs`, primitives in
//! `trianglemesh_primitives.rs`.
use std::fmt;
use std::ptr::{self, NonNull};
use std::slice;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::image::{new_image, Image};
use crate::pointcloud::copy_out;
use crate::util::adopt;

/// The float64 arrays of a mesh with three values per row.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshArray {
    /// N x 3 vertex positions.
    Vertices,
    /// N x 3 vertex normals.
    VertexNormals,
    /// N x 3 vertex colors, RGB in `[0, 1]`.
    VertexColors,
    /// M x 3 triangle normals.
    TriangleNormals,
}

impl MeshArray {
    fn raw(self) -> i32 {
        match self {
            MeshArray::Vertices => sys::O3D_MESH_VERTICES,
            MeshArray::VertexNormals => sys::O3D_MESH_VERTEX_NORMALS,
            MeshArray::VertexColors => sys::O3D_MESH_VERTEX_COLORS,
            MeshArray::TriangleNormals => sys::O3D_MESH_TRIANGLE_NORMALS,
        }
    }
}

/// A triangle mesh: vertices (with optional normals and colors), triangles (with optional normals,
/// per-corner UVs and material ids) and texture images.
///
/// Owns an `o3d_trianglemesh_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and
/// every mutation takes `&mut self`, so borrowed views can never outlive a mutation.
pub struct TriangleMesh {
    raw: NonNull<sys::o3d_trianglemesh_t>,
}

// SAFETY: see the type's documentation.
unsafe impl Send for TriangleMesh {}
unsafe impl Sync for TriangleMesh {}

/// Run a C function writing a new mesh, and own it.
pub(crate) fn new_mesh(f: impl FnOnce(*mut *mut sys::o3d_trianglemesh_t) -> sys::o3d_status) -> Result<TriangleMesh> {
    adopt("mesh", f, |raw| TriangleMesh { raw })
}

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

    /// Take ownership of a raw handle.
    ///
    /// # Safety
    /// `raw` must be a valid mesh handle owned by the caller; it is destroyed on drop.
    pub unsafe fn from_raw(raw: NonNull<sys::o3d_trianglemesh_t>) -> TriangleMesh {
        TriangleMesh { raw }
    }

    /// The raw handle, still owned by `self`.
    pub fn as_raw(&self) -> *const sys::o3d_trianglemesh_t {
        self.raw.as_ptr()
    }

    pub(crate) fn raw_mut(&mut self) -> *mut sys::o3d_trianglemesh_t {
        self.raw.as_ptr()
    }

    /// Deep copy, textures included.
    pub fn try_clone(&self) -> Result<TriangleMesh> {
        // SAFETY: valid source handle.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_clone(out, self.as_raw()) })
    }

    /// Remove all arrays and textures.
    pub fn clear(&mut self) -> Result<()> {
        // SAFETY: valid handle, exclusively borrowed.
        check(unsafe { sys::o3d_trianglemesh_clear(self.raw_mut()) })
    }

    /// Number of vertices.
    pub fn num_vertices(&self) -> Result<usize> {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_num_vertices(&mut n, self.as_raw()) })?;
        Ok(n)
    }

    /// Number of triangles.
    pub fn num_triangles(&self) -> Result<usize> {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_num_triangles(&mut n, self.as_raw()) })?;
        Ok(n)
    }

    fn has(&self, which: i32) -> Result<bool> {
        let mut v = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_has_array(&mut v, self.as_raw(), which) })?;
        Ok(v != 0)
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

    fn set_f64<const N: usize>(&mut self, which: i32, rows: &[[f64; N]]) -> Result<()> {
        // SAFETY: rows.len() rows of N contiguous doubles; copied by the library.
        check(unsafe { sys::o3d_trianglemesh_set_array(self.raw_mut(), which, rows.as_ptr().cast(), rows.len()) })
    }

    fn view_f64<const N: usize>(&self, which: i32) -> Result<&[[f64; N]]> {
        let (mut data, mut n) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_trianglemesh_array_view(&mut data, &mut n, self.as_raw(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&[]);
        }
        // SAFETY: n rows of N doubles, valid until the next mutation, which needs `&mut self`.
        Ok(unsafe { slice::from_raw_parts(data.cast::<[f64; N]>(), n) })
    }

    fn view_f64_mut<const N: usize>(&mut self, which: i32) -> Result<&mut [[f64; N]]> {
        let (mut data, mut n) = (ptr::null_mut(), 0);
        // SAFETY: valid handle, exclusively borrowed, and out-pointers.
        check(unsafe { sys::o3d_trianglemesh_array_mutable_view(&mut data, &mut n, self.raw_mut(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&mut []);
        }
        // SAFETY: as view_f64, unique for the life of the `&mut self` borrow.
        Ok(unsafe { slice::from_raw_parts_mut(data.cast::<[f64; N]>(), n) })
    }

    fn get_f64<const N: usize>(&self, which: i32) -> Result<Vec<[f64; N]>>
    where
        [f64; N]: Default,
    {
        // SAFETY: `out` has room for `cap` rows of N doubles, or is NULL for the count query.
        copy_out::<[f64; N]>(|out, cap, n| unsafe {
            sys::o3d_trianglemesh_get_array(out.cast(), cap, n, self.as_raw(), which)
        })
    }

    /// Replace a three-column array (copied once).
    pub fn set_array(&mut self, which: MeshArray, rows: &[[f64; 3]]) -> Result<()> {
        self.set_f64(which.raw(), rows)
    }

    /// Zero-copy view of a three-column array (empty when absent).
    pub fn array(&self, which: MeshArray) -> Result<&[[f64; 3]]> {
        self.view_f64(which.raw())
    }

    /// Writable zero-copy view of a three-column array.
    pub fn array_mut(&mut self, which: MeshArray) -> Result<&mut [[f64; 3]]> {
        self.view_f64_mut(which.raw())
    }

    /// Copy of a three-column array (`o3d_trianglemesh_get_array`).
    pub fn array_to_vec(&self, which: MeshArray) -> Result<Vec<[f64; 3]>> {
        self.get_f64(which.raw())
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
        self.set_f64(sys::O3D_MESH_TRIANGLE_UVS, uvs)
    }

    /// Zero-copy view of the per-corner UVs.
    pub fn triangle_uvs(&self) -> Result<&[[f64; 2]]> {
        self.view_f64(sys::O3D_MESH_TRIANGLE_UVS)
    }

    /// Writable view of the per-corner UVs.
    pub fn triangle_uvs_mut(&mut self) -> Result<&mut [[f64; 2]]> {
        self.view_f64_mut(sys::O3D_MESH_TRIANGLE_UVS)
    }

    /// Copy of the per-corner UVs.
    pub fn triangle_uvs_to_vec(&self) -> Result<Vec<[f64; 2]>> {
        self.get_f64(sys::O3D_MESH_TRIANGLE_UVS)
    }

    // ---- int32 arrays ----

    fn set_i32<const N: usize>(&mut self, which: i32, rows: &[[i32; N]]) -> Result<()> {
        // SAFETY: rows.len() rows of N contiguous ints; copied by the library.
        check(unsafe { sys::o3d_trianglemesh_set_index_array(self.raw_mut(), which, rows.as_ptr().cast(), rows.len()) })
    }

    fn view_i32<const N: usize>(&self, which: i32) -> Result<&[[i32; N]]> {
        let (mut data, mut n) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_trianglemesh_index_array_view(&mut data, &mut n, self.as_raw(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&[]);
        }
        // SAFETY: n rows of N ints, valid until the next mutation.
        Ok(unsafe { slice::from_raw_parts(data.cast::<[i32; N]>(), n) })
    }

    fn view_i32_mut<const N: usize>(&mut self, which: i32) -> Result<&mut [[i32; N]]> {
        let (mut data, mut n) = (ptr::null_mut(), 0);
        // SAFETY: valid handle, exclusively borrowed, and out-pointers.
        check(unsafe { sys::o3d_trianglemesh_index_array_mutable_view(&mut data, &mut n, self.raw_mut(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&mut []);
        }
        // SAFETY: as view_i32, unique for the `&mut self` borrow.
        Ok(unsafe { slice::from_raw_parts_mut(data.cast::<[i32; N]>(), n) })
    }

    fn get_i32<const N: usize>(&self, which: i32) -> Result<Vec<[i32; N]>>
    where
        [i32; N]: Default,
    {
        // SAFETY: `out` has room for `cap` rows of N ints, or is NULL.
        copy_out::<[i32; N]>(|out, cap, n| unsafe {
            sys::o3d_trianglemesh_get_index_array(out.cast(), cap, n, self.as_raw(), which)
        })
    }

    /// Replace the triangles (vertex indices).
    pub fn set_triangles(&mut self, triangles: &[[i32; 3]]) -> Result<()> {
        self.set_i32(sys::O3D_MESH_TRIANGLES, triangles)
    }

    /// Zero-copy view of the triangles.
    pub fn triangles(&self) -> Result<&[[i32; 3]]> {
        self.view_i32(sys::O3D_MESH_TRIANGLES)
    }

    /// Writable view of the triangles (indices are re-checked by every operation).
    pub fn triangles_mut(&mut self) -> Result<&mut [[i32; 3]]> {
        self.view_i32_mut(sys::O3D_MESH_TRIANGLES)
    }

    /// Copy of the triangles.
    pub fn triangles_to_vec(&self) -> Result<Vec<[i32; 3]>> {
        self.get_i32(sys::O3D_MESH_TRIANGLES)
    }

    /// Replace the per-triangle material ids.
    pub fn set_triangle_material_ids(&mut self, ids: &[i32]) -> Result<()> {
        // SAFETY: ids.len() ints; copied by the library.
        check(unsafe {
            sys::o3d_trianglemesh_set_index_array(
                self.raw_mut(),
                sys::O3D_MESH_TRIANGLE_MATERIAL_IDS,
                ids.as_ptr(),
                ids.len(),
            )
        })
    }

    /// Zero-copy view of the per-triangle material ids.
    pub fn triangle_material_ids(&self) -> Result<&[i32]> {
        let rows = self.view_i32::<1>(sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)?;
        // SAFETY: [i32; 1] has the layout of i32 (as_flattened needs Rust 1.80).
        Ok(unsafe { slice::from_raw_parts(rows.as_ptr().cast::<i32>(), rows.len()) })
    }

    /// Writable view of the per-triangle material ids.
    pub fn triangle_material_ids_mut(&mut self) -> Result<&mut [i32]> {
        let rows = self.view_i32_mut::<1>(sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)?;
        // SAFETY: [i32; 1] has the layout of i32.
        Ok(unsafe { slice::from_raw_parts_mut(rows.as_mut_ptr().cast::<i32>(), rows.len()) })
    }

    /// Copy of the per-triangle material ids.
    pub fn triangle_material_ids_to_vec(&self) -> Result<Vec<i32>> {
        Ok(self.get_i32::<1>(sys::O3D_MESH_TRIANGLE_MATERIAL_IDS)?.into_iter().map(|[id]| id).collect())
    }

    // ---- textures ----

    /// Number of texture images.
    pub fn texture_count(&self) -> Result<usize> {
        let mut n = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_trianglemesh_texture_count(&mut n, self.as_raw()) })?;
        Ok(n)
    }

    /// A copy of texture `index` (out of range → Err).
    pub fn texture(&self, index: usize) -> Result<Image> {
        // SAFETY: valid handle and out-pointer.
        new_image(|out| unsafe { sys::o3d_trianglemesh_get_texture(out, self.as_raw(), index) })
    }

    /// Copies of every texture.
    pub fn textures(&self) -> Result<Vec<Image>> {
        (0..self.texture_count()?).map(|i| self.texture(i)).collect()
    }

    /// Append a copy of `image` to the textures.
    pub fn add_texture(&mut self, image: &Image) -> Result<()> {
        // SAFETY: valid handles.
        check(unsafe { sys::o3d_trianglemesh_add_texture(self.raw_mut(), image.as_raw()) })
    }

    /// Remove all textures.
    pub fn clear_textures(&mut self) -> Result<()> {
        // SAFETY: valid handle.
        check(unsafe { sys::o3d_trianglemesh_clear_textures(self.raw_mut()) })
    }

    /// Concatenate `other` (Open3D `mesh += other`), re-indexing its triangles.
    pub fn append(&mut self, other: &TriangleMesh) -> Result<()> {
        // SAFETY: two valid handles; `self` is exclusive so they differ.
        check(unsafe { sys::o3d_trianglemesh_append(self.raw_mut(), other.as_raw()) })
    }
}

impl Drop for TriangleMesh {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once.
        unsafe { sys::o3d_trianglemesh_destroy(self.raw.as_ptr()) }
    }
}

impl Clone for TriangleMesh {
    /// Deep copy. Panics if the library cannot copy; see [`TriangleMesh::try_clone`].
    fn clone(&self) -> Self {
        self.try_clone().unwrap_or_else(|e| panic!("o3d_trianglemesh_clone failed: {e}"))
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
