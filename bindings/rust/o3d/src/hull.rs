//! Convex hulls (through Qhull) and hidden-point removal (Katz, Tal, Basri 2007).
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;

/// Run a C call writing a new mesh and, per mesh vertex, the index of the input point it came from
/// (at most `inputs` of them, the input's size).
fn mesh_and_indices(
    inputs: usize,
    f: impl FnOnce(*mut *mut sys::o3d_trianglemesh_t, *mut i32, usize, *mut usize) -> sys::o3d_status,
) -> Result<(TriangleMesh, Vec<i32>)> {
    let mut indices = vec![0i32; inputs];
    let (mut raw, mut n) = (ptr::null_mut(), 0usize);
    let status = f(&mut raw, indices.as_mut_ptr(), indices.len(), &mut n);
    // Own whatever was written before looking at the status, so nothing leaks.
    // SAFETY: a handle written by the library belongs to the caller.
    let mesh = NonNull::new(raw).map(|raw| unsafe { TriangleMesh::from_raw(raw) });
    check(status)?;
    let mesh =
        mesh.ok_or_else(|| Error::new(ErrorCode::Internal, "the library reported success but returned no mesh"))?;
    indices.truncate(n.min(inputs));
    Ok((mesh, indices))
}

impl PointCloud {
    /// Convex hull of the points (at least 4, not all coplanar unless `joggle_inputs`, which lets
    /// Qhull perturb the input): outward-facing triangles, and for each hull vertex the index of
    /// the point it came from.
    pub fn compute_convex_hull(&self, joggle_inputs: bool) -> Result<(TriangleMesh, Vec<i32>)> {
        mesh_and_indices(self.try_len()?, |out, idx, cap, n| {
            // SAFETY: valid handle; `idx` has room for `cap` ints; out-pointers valid.
            unsafe { sys::o3d_pointcloud_compute_convex_hull(out, idx, cap, n, self.as_raw(), joggle_inputs as i32) }
        })
    }

    /// The points visible from `camera_location` (spherical flipping with `radius` > 0, then the
    /// convex hull of the flipped points and the camera): the hull mesh, and the visible points'
    /// indices.
    pub fn hidden_point_removal(&self, camera_location: [f64; 3], radius: f64) -> Result<(TriangleMesh, Vec<i32>)> {
        mesh_and_indices(self.try_len()?, |out, idx, cap, n| {
            // SAFETY: valid handle; 3 doubles; `idx` has room for `cap` ints.
            unsafe {
                sys::o3d_pointcloud_hidden_point_removal(
                    out,
                    idx,
                    cap,
                    n,
                    self.as_raw(),
                    camera_location.as_ptr(),
                    radius,
                )
            }
        })
    }
}

impl TriangleMesh {
    /// Convex hull of the vertices, and for each hull vertex the index of the vertex it came from.
    pub fn compute_convex_hull(&self, joggle_inputs: bool) -> Result<(TriangleMesh, Vec<i32>)> {
        mesh_and_indices(self.num_vertices()?, |out, idx, cap, n| {
            // SAFETY: valid handle; `idx` has room for `cap` ints; out-pointers valid.
            unsafe { sys::o3d_trianglemesh_compute_convex_hull(out, idx, cap, n, self.as_raw(), joggle_inputs as i32) }
        })
    }
}
