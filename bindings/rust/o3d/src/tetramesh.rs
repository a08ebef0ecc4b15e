//! `TetraMesh` (o3d.geometry.TetraMesh): vertices and tetrahedra, the Delaunay tetrahedralization of a
//! point cloud and iso-surfaces of per-vertex values (marching tetrahedra).
use std::fmt;
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::array::{impl_arrays, Family};
use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::PointCloud;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::handle;

include!("generated/tetramesh.rs");

handle! {
    /// Vertices (N x 3) and tetrahedra (M quadruples of vertex indices). Tetra indices may hold any
    /// value; every operation that follows them checks them.
    ///
    /// Owns an `o3d_tetramesh_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and every
    /// mutation takes `&mut self`, so borrowed views never outlive a mutation.
    TetraMesh(sys::o3d_tetramesh_t, "tetra mesh"), new_tetramesh, sys::o3d_tetramesh_destroy, sys::o3d_tetramesh_clone
}
impl_arrays!(TetraMesh, sys::o3d_tetramesh_t);

/// The float64 array (`O3D_TETRAMESH_VERTICES`).
const ARRAYS: Family<sys::o3d_tetramesh_t, f64> = Family {
    has: sys::o3d_tetramesh_has_array,
    shape: sys::o3d_tetramesh_array_shape,
    set: sys::o3d_tetramesh_set_array,
    get: sys::o3d_tetramesh_get_array,
    view: sys::o3d_tetramesh_array_view,
    view_mut: sys::o3d_tetramesh_array_mutable_view,
    set_f32: Some(sys::o3d_tetramesh_set_array_f32),
};
/// The int32 array (`O3D_TETRAMESH_TETRAS`).
const INDICES: Family<sys::o3d_tetramesh_t, i32> = Family {
    has: sys::o3d_tetramesh_has_array,
    shape: sys::o3d_tetramesh_array_shape,
    set: sys::o3d_tetramesh_set_index_array,
    get: sys::o3d_tetramesh_get_index_array,
    view: sys::o3d_tetramesh_index_array_view,
    view_mut: sys::o3d_tetramesh_index_array_mutable_view,
    set_f32: None,
};
const VERTICES: i32 = sys::O3D_TETRAMESH_VERTICES;
const TETRAS: i32 = sys::O3D_TETRAMESH_TETRAS;

impl TetraMesh {
    /// A new empty tetra mesh.
    pub fn new() -> Result<TetraMesh> {
        // SAFETY: out-pointer.
        new_tetramesh(|out| unsafe { sys::o3d_tetramesh_create(out) })
    }

    /// A tetra mesh holding `vertices` and `tetras` (indices are checked by every later operation).
    pub fn from_vertices_and_tetras(vertices: &[[f64; 3]], tetras: &[[i32; 4]]) -> Result<TetraMesh> {
        let mut mesh = TetraMesh::new()?;
        mesh.set_vertices(vertices)?;
        mesh.set_tetras(tetras)?;
        Ok(mesh)
    }

    /// True if there are vertices.
    pub fn has_vertices(&self) -> Result<bool> {
        ARRAYS.has(self, VERTICES)
    }

    /// True if there are tetrahedra.
    pub fn has_tetras(&self) -> Result<bool> {
        INDICES.has(self, TETRAS)
    }

    /// Replace the vertices (copied once).
    pub fn set_vertices(&mut self, vertices: &[[f64; 3]]) -> Result<()> {
        ARRAYS.set(self, VERTICES, vertices)
    }

    /// Replace the vertices from float32 input (converted in the single copy).
    pub fn set_vertices_f32(&mut self, vertices: &[[f32; 3]]) -> Result<()> {
        ARRAYS.set_f32(self, VERTICES, vertices)
    }

    /// Zero-copy view of the vertices, borrowed from the mesh.
    pub fn vertices(&self) -> Result<&[[f64; 3]]> {
        ARRAYS.view(self, VERTICES)
    }

    /// Writable zero-copy view of the vertices, for in-place edits.
    pub fn vertices_mut(&mut self) -> Result<&mut [[f64; 3]]> {
        ARRAYS.view_mut(self, VERTICES)
    }

    /// Copy of the vertices.
    pub fn vertices_to_vec(&self) -> Result<Vec<[f64; 3]>> {
        ARRAYS.to_vec(self, VERTICES)
    }

    /// Replace the tetrahedra (quadruples of vertex indices).
    pub fn set_tetras(&mut self, tetras: &[[i32; 4]]) -> Result<()> {
        INDICES.set(self, TETRAS, tetras)
    }

    /// Zero-copy view of the tetrahedra.
    pub fn tetras(&self) -> Result<&[[i32; 4]]> {
        INDICES.view(self, TETRAS)
    }

    /// Writable zero-copy view of the tetrahedra.
    pub fn tetras_mut(&mut self) -> Result<&mut [[i32; 4]]> {
        INDICES.view_mut(self, TETRAS)
    }

    /// Copy of the tetrahedra.
    pub fn tetras_to_vec(&self) -> Result<Vec<[i32; 4]>> {
        INDICES.to_vec(self, TETRAS)
    }

    /// The 3-D Delaunay tetrahedralization of the cloud's points (Qhull; at least 4 points, not all
    /// coplanar), and for each tetra-mesh vertex the index of the input point it is.
    /// @see TetraMesh.create_from_point_cloud
    pub fn create_from_point_cloud(cloud: &PointCloud) -> Result<(TetraMesh, Vec<i32>)> {
        // A vertex is an input point, so the cloud's size is room enough for the map.
        let mut point_map = vec![0i32; cloud.try_len()?];
        let (mut raw, mut n) = (ptr::null_mut(), 0usize);
        // SAFETY: valid handle; `point_map` has room for its length in ints; out-pointers valid.
        let status = unsafe {
            sys::o3d_tetramesh_create_from_point_cloud(
                &mut raw,
                point_map.as_mut_ptr(),
                point_map.len(),
                &mut n,
                cloud.as_raw(),
            )
        };
        // Own whatever was written before looking at the status, so nothing leaks.
        // SAFETY: a handle written by the library belongs to the caller.
        let mesh = NonNull::new(raw).map(|raw| unsafe { TetraMesh::from_raw(raw) });
        check(status)?;
        let mesh = mesh.ok_or_else(|| {
            Error::new(ErrorCode::Internal, "the library reported success but returned no tetra mesh")
        })?;
        point_map.truncate(n.min(point_map.len()));
        Ok((mesh, point_map))
    }

    /// The triangle mesh of the iso-surface `values == level`, with `values` one per vertex, linear on
    /// each tetrahedron (marching tetrahedra; vertices on a shared edge are shared).
    /// @see TetraMesh.extract_triangle_mesh
    pub fn extract_triangle_mesh(&self, values: &[f64], level: f64) -> Result<TriangleMesh> {
        // SAFETY: valid handle; values.len() doubles, copied by the library.
        new_mesh(|out| unsafe {
            sys::o3d_tetramesh_extract_triangle_mesh(out, self.as_raw(), values.as_ptr(), values.len(), level)
        })
    }
}

impl fmt::Debug for TetraMesh {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("TetraMesh")
            .field("vertices", &self.num_vertices().unwrap_or(0))
            .field("tetras", &self.num_tetras().unwrap_or(0))
            .finish()
    }
}
