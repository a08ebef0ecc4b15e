//! Removing a mesh's vertices or triangles by index or by mask (Open3D's `TriangleMesh.remove_*_by_*`), e.g.
//! trimming a Poisson surface where its densities are low. What stays keeps its order and attributes; on an
//! error the mesh is unchanged.
use o3d_sys as sys;

use crate::error::{check, Result};
use crate::trianglemesh::TriangleMesh;

/// A `bool` slice as the C API's bytes (0 or 1: Rust's `bool` has the layout of a `u8` holding one of them).
fn mask_bytes(mask: &[bool]) -> *const u8 {
    mask.as_ptr().cast()
}

impl TriangleMesh {
    /// Remove the vertices at `indices` (repeats allowed) and every triangle that uses one of them.
    pub fn remove_vertices_by_index(&mut self, indices: &[i32]) -> Result<&mut Self> {
        // SAFETY: a valid handle, held exclusively; indices.len() ints, read during the call.
        check(unsafe {
            sys::o3d_trianglemesh_remove_vertices_by_index(self.raw_mut(), indices.as_ptr(), indices.len())
        })?;
        Ok(self)
    }

    /// Remove the vertices whose `mask` entry is true (one per vertex) and every triangle that uses one of them.
    pub fn remove_vertices_by_mask(&mut self, mask: &[bool]) -> Result<&mut Self> {
        // SAFETY: a valid handle, held exclusively; mask.len() bytes, read during the call.
        check(unsafe { sys::o3d_trianglemesh_remove_vertices_by_mask(self.raw_mut(), mask_bytes(mask), mask.len()) })?;
        Ok(self)
    }

    /// Remove the triangles at `indices` (repeats allowed); every vertex stays.
    pub fn remove_triangles_by_index(&mut self, indices: &[i32]) -> Result<&mut Self> {
        // SAFETY: a valid handle, held exclusively; indices.len() ints, read during the call.
        check(unsafe {
            sys::o3d_trianglemesh_remove_triangles_by_index(self.raw_mut(), indices.as_ptr(), indices.len())
        })?;
        Ok(self)
    }

    /// Remove the triangles whose `mask` entry is true (one per triangle); every vertex stays.
    pub fn remove_triangles_by_mask(&mut self, mask: &[bool]) -> Result<&mut Self> {
        // SAFETY: a valid handle, held exclusively; mask.len() bytes, read during the call.
        check(unsafe { sys::o3d_trianglemesh_remove_triangles_by_mask(self.raw_mut(), mask_bytes(mask), mask.len()) })?;
        Ok(self)
    }
}
