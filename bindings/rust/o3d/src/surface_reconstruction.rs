//! Surface reconstruction from point clouds (Open3D's `TriangleMesh.create_from_point_cloud_*`): screened
//! Poisson, ball pivoting and alpha shapes, each with a `_with_progress` twin taking a progress closure
//! (see `progress.rs`). `PoissonOptions` is generated from the C header.
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::feature::Feature;
use crate::pointcloud::PointCloud;
use crate::progress::progress_pair;
use crate::tetramesh::TetraMesh;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::options;
use crate::ProgressOptions;

include!("generated/surface_reconstruction.rs");

/// Own the mesh and the densities a Poisson call wrote, then check its status (so nothing leaks on
/// failure); the densities are a 1 x V feature, one value per mesh vertex.
fn poisson_outputs(
    status: sys::o3d_status,
    mesh: *mut sys::o3d_trianglemesh_t,
    densities: *mut sys::o3d_feature_t,
) -> Result<(TriangleMesh, Vec<f64>)> {
    // SAFETY: handles written by the library belong to the caller.
    let mesh = NonNull::new(mesh).map(|raw| unsafe { TriangleMesh::from_raw(raw) });
    // SAFETY: as above; the feature is read once and dropped here.
    let densities = NonNull::new(densities).map(|raw| unsafe { Feature::from_raw(raw) });
    check(status)?;
    let missing =
        |what: &str| Error::new(ErrorCode::Internal, format!("the library reported success but returned no {what}"));
    let mesh = mesh.ok_or_else(|| missing("mesh"))?;
    let densities = densities.ok_or_else(|| missing("densities"))??;
    Ok((mesh, densities.data().to_vec()))
}

/// The tetra mesh and point map an alpha shape reuses (NULL and none when not given).
fn reused_tetras(tetras: Option<(&TetraMesh, &[i32])>) -> (*const sys::o3d_tetramesh_t, *const i32, usize) {
    match tetras {
        Some((mesh, point_map)) => (mesh.as_raw(), point_map.as_ptr(), point_map.len()),
        None => (ptr::null(), ptr::null(), 0),
    }
}

impl TriangleMesh {
    progress_pair! {
        /// Screened Poisson surface reconstruction (Kazhdan & Hoppe 2013) of a cloud with normals, on an
        /// adaptive octree: a watertight mesh (colored when the cloud is), and per vertex the sampling
        /// density there as an octree depth (trim the mesh where it is low, as with Open3D's densities).
        /// @see TriangleMesh.create_from_point_cloud_poisson
        pub fn create_from_point_cloud_poisson;
        /// As [`Self::create_from_point_cloud_poisson`], reporting the fraction of the work done to
        /// `progress` on this thread. Return `ControlFlow::Break(())` to stop with
        /// [`crate::ErrorCode::Cancelled`]; a panic cancels and resumes.
        pub fn create_from_point_cloud_poisson_with_progress(
            cloud: &PointCloud,
            options: &PoissonOptions,
        ) -> Result<(TriangleMesh, Vec<f64>)>;
        |callback, user_data| {
            let mut opts = options.to_raw()?;
            (opts.progress, opts.user_data) = (callback, user_data);
            let (mut mesh, mut densities) = (ptr::null_mut(), ptr::null_mut());
            // SAFETY: a valid handle, out-pointers and an options struct that live for the call.
            let status = unsafe {
                sys::o3d_trianglemesh_create_from_point_cloud_poisson(&mut mesh, &mut densities, cloud.as_raw(), &opts)
            };
            poisson_outputs(status, mesh, densities)
        }
    }

    progress_pair! {
        /// Ball pivoting (Bernardini et al. 1999): a ball of each radius in turn (increasing) pivots about
        /// the front's edges. The mesh's vertices are the cloud's points (with their normals and colors),
        /// its triangles wound to agree with the normals; the cloud needs normals and every radius must be
        /// finite and positive. @see TriangleMesh.create_from_point_cloud_ball_pivoting
        pub fn create_from_point_cloud_ball_pivoting;
        /// As [`Self::create_from_point_cloud_ball_pivoting`] with a progress closure (see
        /// [`Self::create_from_point_cloud_poisson_with_progress`]).
        pub fn create_from_point_cloud_ball_pivoting_with_progress(
            cloud: &PointCloud,
            radii: &[f64],
            options: &ProgressOptions,
        ) -> Result<TriangleMesh>;
        |callback, user_data| {
            let mut opts = options.to_raw()?;
            (opts.progress, opts.user_data) = (callback, user_data);
            // SAFETY: a valid handle; radii.len() doubles; an options struct that lives for the call.
            new_mesh(|out| unsafe {
                sys::o3d_trianglemesh_create_from_point_cloud_ball_pivoting(
                    out,
                    cloud.as_raw(),
                    radii.as_ptr(),
                    radii.len(),
                    &opts,
                )
            })
        }
    }

    progress_pair! {
        /// The alpha shape (Edelsbrunner & Muecke 1994): the boundary of the Delaunay tetrahedra whose
        /// circumradius is below `alpha` (finite, > 0), wound outwards. `tetras` reuses a tetrahedralization
        /// of the same cloud and its point map from [`TetraMesh::create_from_point_cloud`] (`None`: computed
        /// here). @see TriangleMesh.create_from_point_cloud_alpha_shape
        pub fn create_from_point_cloud_alpha_shape;
        /// As [`Self::create_from_point_cloud_alpha_shape`] with a progress closure (see
        /// [`Self::create_from_point_cloud_poisson_with_progress`]).
        pub fn create_from_point_cloud_alpha_shape_with_progress(
            cloud: &PointCloud,
            alpha: f64,
            tetras: Option<(&TetraMesh, &[i32])>,
            options: &ProgressOptions,
        ) -> Result<TriangleMesh>;
        |callback, user_data| {
            let mut opts = options.to_raw()?;
            (opts.progress, opts.user_data) = (callback, user_data);
            let (tetramesh, point_map, num_point_map) = reused_tetras(tetras);
            // SAFETY: valid handles (or NULL); num_point_map ints; an options struct that lives for the call.
            new_mesh(|out| unsafe {
                sys::o3d_trianglemesh_create_from_point_cloud_alpha_shape(
                    out,
                    cloud.as_raw(),
                    alpha,
                    tetramesh,
                    point_map,
                    num_point_map,
                    &opts,
                )
            })
        }
    }
}
