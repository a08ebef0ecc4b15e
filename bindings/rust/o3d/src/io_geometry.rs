//! Reading and writing triangle meshes, images and camera models (re-exported from [`crate::io`]).
use std::path::Path;

use o3d_sys as sys;

use crate::camera::{new_trajectory, CameraTrajectory, PinholeCameraParameters, PinholeIntrinsic};
use crate::error::{check, Result};
use crate::image::{new_image, Image};
use crate::io::{c_path, c_string, new_buffer, Buffer};
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::options;

include!("generated/io_geometry.rs");

// ---- triangle meshes ----

/// Read a mesh from `path` (`format`: `"auto"` for the extension). OBJ also reads its materials.
pub fn read_triangle_mesh(path: impl AsRef<Path>, format: &str, options: &MeshReadOptions) -> Result<TriangleMesh> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: NUL-terminated strings and valid options.
    new_mesh(|out| unsafe { sys::o3d_io_read_triangle_mesh(out, path.as_ptr(), format.as_ptr(), &opts) })
}

/// Write `mesh` to `path` (`format`: `"auto"` for the extension).
pub fn write_triangle_mesh(
    path: impl AsRef<Path>,
    mesh: &TriangleMesh,
    format: &str,
    options: &MeshWriteOptions,
) -> Result<()> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: NUL-terminated strings, valid handle and options.
    check(unsafe { sys::o3d_io_write_triangle_mesh(path.as_ptr(), mesh.as_raw(), format.as_ptr(), &opts) })
}

/// Read a mesh from in-memory file contents: `"ply"`, `"stl"`, `"off"`, `"obj"` or `"glb"`.
pub fn read_triangle_mesh_from_memory(data: &[u8], format: &str, options: &MeshReadOptions) -> Result<TriangleMesh> {
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: data.len() readable bytes; NUL-terminated format; valid options.
    new_mesh(|out| unsafe {
        sys::o3d_io_read_triangle_mesh_from_memory(out, data.as_ptr(), data.len(), format.as_ptr(), &opts)
    })
}

/// Encode `mesh` in `format` into a library-owned [`Buffer`].
pub fn write_triangle_mesh_to_buffer(mesh: &TriangleMesh, format: &str, options: &MeshWriteOptions) -> Result<Buffer> {
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: valid handle, NUL-terminated format, valid options.
    new_buffer(|out| unsafe { sys::o3d_io_write_triangle_mesh_to_memory(out, mesh.as_raw(), format.as_ptr(), &opts) })
}

/// Encode `mesh` in `format` (e.g. `"ply"`) into a byte vector.
pub fn write_triangle_mesh_to_memory(mesh: &TriangleMesh, format: &str, options: &MeshWriteOptions) -> Result<Vec<u8>> {
    write_triangle_mesh_to_buffer(mesh, format, options)?.to_vec()
}

// ---- images ----

/// JPEG quality for [`write_image`]: `None` means the default (90).
fn quality_raw(quality: Option<i32>) -> i32 {
    quality.unwrap_or(-1)
}

/// Read an image: PNG, JPEG, PPM or PGM (`format`: `"auto"` for the extension).
pub fn read_image(path: impl AsRef<Path>, format: &str) -> Result<Image> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    // SAFETY: NUL-terminated strings.
    new_image(|out| unsafe { sys::o3d_io_read_image(out, path.as_ptr(), format.as_ptr()) })
}

/// Write an image; `quality` is the JPEG quality 1..=100 (`None`: 90), ignored by other formats.
pub fn write_image(path: impl AsRef<Path>, image: &Image, format: &str, quality: Option<i32>) -> Result<()> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    // SAFETY: NUL-terminated strings and a valid handle.
    check(unsafe { sys::o3d_io_write_image(path.as_ptr(), image.as_raw(), format.as_ptr(), quality_raw(quality)) })
}

/// Decode an image from in-memory file contents (`format` required, e.g. `"png"`).
pub fn read_image_from_memory(data: &[u8], format: &str) -> Result<Image> {
    let format = c_string("format", format)?;
    // SAFETY: data.len() readable bytes and a NUL-terminated format.
    new_image(|out| unsafe { sys::o3d_io_read_image_from_memory(out, data.as_ptr(), data.len(), format.as_ptr()) })
}

/// Encode an image in `format` into a library-owned [`Buffer`].
pub fn write_image_to_buffer(image: &Image, format: &str, quality: Option<i32>) -> Result<Buffer> {
    let format = c_string("format", format)?;
    // SAFETY: valid handle and NUL-terminated format.
    new_buffer(|out| unsafe {
        sys::o3d_io_write_image_to_memory(out, image.as_raw(), format.as_ptr(), quality_raw(quality))
    })
}

/// Encode an image in `format` into a byte vector.
pub fn write_image_to_memory(image: &Image, format: &str, quality: Option<i32>) -> Result<Vec<u8>> {
    write_image_to_buffer(image, format, quality)?.to_vec()
}

// ---- camera models ----

/// Read a PinholeCameraIntrinsic JSON file.
pub fn read_pinhole_camera_intrinsic(path: impl AsRef<Path>) -> Result<PinholeIntrinsic> {
    let path = c_path(path.as_ref())?;
    let mut out = sys::o3d_pinhole_intrinsic_t::default();
    // SAFETY: NUL-terminated path and a writable struct.
    check(unsafe { sys::o3d_io_read_pinhole_camera_intrinsic(&mut out, path.as_ptr()) })?;
    Ok(PinholeIntrinsic::from_raw(out))
}

/// Write a PinholeCameraIntrinsic JSON file.
pub fn write_pinhole_camera_intrinsic(path: impl AsRef<Path>, intrinsic: &PinholeIntrinsic) -> Result<()> {
    let path = c_path(path.as_ref())?;
    let raw = intrinsic.to_raw();
    // SAFETY: NUL-terminated path and a valid struct.
    check(unsafe { sys::o3d_io_write_pinhole_camera_intrinsic(path.as_ptr(), &raw) })
}

/// Read a PinholeCameraParameters JSON file (intrinsic and world-to-camera extrinsic).
pub fn read_pinhole_camera_parameters(path: impl AsRef<Path>) -> Result<PinholeCameraParameters> {
    let path = c_path(path.as_ref())?;
    let mut intrinsic = sys::o3d_pinhole_intrinsic_t::default();
    let mut extrinsic = [[0.0f64; 4]; 4];
    // SAFETY: NUL-terminated path, a writable struct and 16 doubles.
    check(unsafe {
        sys::o3d_io_read_pinhole_camera_parameters(&mut intrinsic, extrinsic.as_mut_ptr().cast(), path.as_ptr())
    })?;
    Ok(PinholeCameraParameters { intrinsic: PinholeIntrinsic::from_raw(intrinsic), extrinsic })
}

/// Write a PinholeCameraParameters JSON file.
pub fn write_pinhole_camera_parameters(path: impl AsRef<Path>, parameters: &PinholeCameraParameters) -> Result<()> {
    let path = c_path(path.as_ref())?;
    let raw = parameters.intrinsic.to_raw();
    // SAFETY: NUL-terminated path, a valid struct and 16 doubles.
    check(unsafe {
        sys::o3d_io_write_pinhole_camera_parameters(path.as_ptr(), &raw, parameters.extrinsic.as_ptr().cast())
    })
}

/// Read a trajectory: `"json"` or `"log"` (`"auto"`: by extension).
pub fn read_pinhole_camera_trajectory(path: impl AsRef<Path>, format: &str) -> Result<CameraTrajectory> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    // SAFETY: NUL-terminated strings.
    new_trajectory(|out| unsafe { sys::o3d_io_read_pinhole_camera_trajectory(out, path.as_ptr(), format.as_ptr()) })
}

/// Write a trajectory: `"json"` or `"log"` (`"auto"`: by extension).
pub fn write_pinhole_camera_trajectory(
    path: impl AsRef<Path>,
    trajectory: &CameraTrajectory,
    format: &str,
) -> Result<()> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    // SAFETY: NUL-terminated strings and a valid handle.
    check(unsafe { sys::o3d_io_write_pinhole_camera_trajectory(path.as_ptr(), trajectory.as_raw(), format.as_ptr()) })
}
