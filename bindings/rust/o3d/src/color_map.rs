//! Colour-map optimization (o3d.pipelines.color_map): [`run_rigid_optimizer`] and
//! [`run_non_rigid_optimizer`] refine the poses of the RGB-D images a mesh was built from, then colour
//! its vertices from them. The options are generated from the C header.
use std::ptr;

use o3d_sys as sys;

use crate::camera::{new_trajectory, CameraTrajectory};
use crate::error::Result;
use crate::rgbd::RgbdImage;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::options;

include!("generated/color_map.rs");

type Run<O> = unsafe extern "C" fn(
    *mut *mut sys::o3d_trianglemesh_t,
    *mut *mut sys::o3d_camera_trajectory_t,
    *const sys::o3d_trianglemesh_t,
    *const *const sys::o3d_rgbd_image_t,
    usize,
    *const sys::o3d_camera_trajectory_t,
    *const O,
) -> sys::o3d_status;

/// One optimizer call: the images as an array of C handles, both outputs owned.
fn run<O>(
    run: Run<O>,
    mesh: &TriangleMesh,
    images: &[RgbdImage],
    trajectory: &CameraTrajectory,
    opts: &O,
) -> Result<(TriangleMesh, CameraTrajectory)> {
    let raw: Vec<*const sys::o3d_rgbd_image_t> = images.iter().map(RgbdImage::as_raw).collect();
    let mut refined = ptr::null_mut();
    // SAFETY: valid handles, `raw.len()` image handles and an options struct that live for the call.
    let colored = new_mesh(|out| unsafe {
        run(out, &mut refined, mesh.as_raw(), raw.as_ptr(), raw.len(), trajectory.as_raw(), opts)
    })?;
    // The call succeeded, so it also wrote the refined trajectory, now ours to own.
    let refined = new_trajectory(|out| {
        // SAFETY: `out` is a valid pointer to write the handle to.
        unsafe { *out = refined };
        sys::O3D_OK
    })?;
    Ok((colored, refined))
}

/// Refine each image's pose (`images[i]` was taken from the trajectory's pose `i`), then colour a
/// copy of the mesh: (coloured mesh, refined trajectory). Colour is 8-bit RGB or float intensity,
/// depth float metres, each the size its intrinsic says.
pub fn run_rigid_optimizer(
    mesh: &TriangleMesh,
    images: &[RgbdImage],
    trajectory: &CameraTrajectory,
    option: &ColorMapRigidOptions,
) -> Result<(TriangleMesh, CameraTrajectory)> {
    run(sys::o3d_color_map_run_rigid_optimizer, mesh, images, trajectory, &option.to_raw()?)
}

/// As [`run_rigid_optimizer`], also refining a grid of anchor offsets that warps each image (the
/// warps are not returned).
pub fn run_non_rigid_optimizer(
    mesh: &TriangleMesh,
    images: &[RgbdImage],
    trajectory: &CameraTrajectory,
    option: &ColorMapNonRigidOptions,
) -> Result<(TriangleMesh, CameraTrajectory)> {
    run(sys::o3d_color_map_run_non_rigid_optimizer, mesh, images, trajectory, &option.to_raw()?)
}
