//! Reading and writing (o3d.io): point clouds (PLY, PCD, XYZ, XYZN, XYZRGB, PTS), triangle meshes
//! (PLY, OBJ, STL, OFF, glTF/GLB), images (PNG, JPEG, PPM, PGM) and camera models (JSON, .log), to
//! files or memory; features (Open3D's binary layout) and pose graphs (Open3D's JSON).
//!
//! Formats are named as in Open3D (`"ply"`, `"pcd"`, ...); `"auto"` or `""` picks the format from
//! the file extension. Paths must be valid UTF-8 (anything else is an `InvalidArgument` error).
use std::ffi::CString;
use std::fmt;
use std::path::Path;
use std::ptr::{self, NonNull};
use std::slice;

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::{new_cloud, PointCloud};
use crate::util::init_struct;

pub use crate::feature::{read_feature, write_feature};
pub use crate::io_geometry::*;
pub use crate::posegraph::{read_pose_graph, write_pose_graph};

/// Read options (o3d.io.read_point_cloud keyword arguments).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// Drop points with a NaN coordinate.
    pub remove_nan_points: bool,
    /// Drop points with an infinite coordinate.
    pub remove_infinite_points: bool,
}

/// Write options (o3d.io.write_point_cloud keyword arguments).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct WriteOptions {
    /// PLY/PCD: text instead of binary.
    pub write_ascii: bool,
    /// PCD: binary_compressed (LZF).
    pub compressed: bool,
}

impl ReadOptions {
    fn to_raw(self) -> Result<sys::o3d_read_options_t> {
        // SAFETY: o3d_read_options_t is plain numbers and nullable pointers; o3d_read_options_init is its init.
        let mut raw = unsafe { init_struct(|p, n| sys::o3d_read_options_init(p, n)) }?;
        raw.remove_nan_points = self.remove_nan_points as i32;
        raw.remove_infinite_points = self.remove_infinite_points as i32;
        Ok(raw)
    }
}

impl WriteOptions {
    fn to_raw(self) -> Result<sys::o3d_write_options_t> {
        // SAFETY: o3d_write_options_t is plain numbers and nullable pointers; o3d_write_options_init is its init.
        let mut raw = unsafe { init_struct(|p, n| sys::o3d_write_options_init(p, n)) }?;
        raw.write_ascii = self.write_ascii as i32;
        raw.compressed = self.compressed as i32;
        Ok(raw)
    }
}

pub(crate) fn c_string(what: &str, s: &str) -> Result<CString> {
    CString::new(s).map_err(|_| Error::new(ErrorCode::InvalidArgument, format!("{what} {s:?} contains a NUL byte")))
}

pub(crate) fn c_path(path: &Path) -> Result<CString> {
    let s = path
        .to_str()
        .ok_or_else(|| Error::new(ErrorCode::InvalidArgument, format!("path {} is not valid UTF-8", path.display())))?;
    c_string("path", s)
}

/// Read a cloud from `path` (`format`: `"auto"` for the extension).
pub fn read_point_cloud(path: impl AsRef<Path>, format: &str, options: &ReadOptions) -> Result<PointCloud> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: NUL-terminated strings and a valid options struct.
    new_cloud(|out| unsafe { sys::o3d_io_read_point_cloud(out, path.as_ptr(), format.as_ptr(), &opts) })
}

/// Write `cloud` to `path` (`format`: `"auto"` for the extension).
pub fn write_point_cloud(
    path: impl AsRef<Path>,
    cloud: &PointCloud,
    format: &str,
    options: &WriteOptions,
) -> Result<()> {
    let path = c_path(path.as_ref())?;
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: NUL-terminated strings, valid handle and options struct.
    check(unsafe { sys::o3d_io_write_point_cloud(path.as_ptr(), cloud.as_raw(), format.as_ptr(), &opts) })
}

/// Read a cloud from in-memory file contents; `format` is required (e.g. `"pcd"`).
pub fn read_point_cloud_from_memory(data: &[u8], format: &str, options: &ReadOptions) -> Result<PointCloud> {
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: data.len() readable bytes; NUL-terminated format; valid options.
    new_cloud(|out| unsafe {
        sys::o3d_io_read_point_cloud_from_memory(out, data.as_ptr(), data.len(), format.as_ptr(), &opts)
    })
}

/// Bytes owned by the library (`o3d_buffer_t`), e.g. an encoded point cloud.
pub struct Buffer {
    raw: NonNull<sys::o3d_buffer_t>,
}

// SAFETY: immutable after creation; every accessor is a const call.
unsafe impl Send for Buffer {}
unsafe impl Sync for Buffer {}

impl Buffer {
    /// Zero-copy view of the bytes.
    pub fn as_bytes(&self) -> Result<&[u8]> {
        let (mut data, mut size) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_buffer_view(&mut data, &mut size, self.raw.as_ptr()) })?;
        if data.is_null() || size == 0 {
            return Ok(&[]);
        }
        // SAFETY: `size` bytes valid until the buffer is destroyed, i.e. while `self` lives.
        Ok(unsafe { slice::from_raw_parts(data, size) })
    }

    /// Copy of the bytes (`o3d_buffer_get_data`).
    pub fn to_vec(&self) -> Result<Vec<u8>> {
        // SAFETY: `out` has room for `cap` bytes or is NULL.
        crate::util::copy_out::<u8>(|out, cap, n| unsafe {
            sys::o3d_buffer_get_data(out, cap, n, self.raw.as_ptr())
        })
    }
}

impl Drop for Buffer {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once.
        unsafe { sys::o3d_buffer_destroy(self.raw.as_ptr()) }
    }
}

impl fmt::Debug for Buffer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Buffer").field("len", &self.as_bytes().map(|b| b.len()).ok()).finish()
    }
}

/// Encode `cloud` in `format` into a library-owned [`Buffer`] (no copy on the Rust side).
pub fn write_point_cloud_to_buffer(cloud: &PointCloud, format: &str, options: &WriteOptions) -> Result<Buffer> {
    let format = c_string("format", format)?;
    let opts = options.to_raw()?;
    // SAFETY: valid handle, NUL-terminated format, valid options, out-pointer.
    new_buffer(|out| unsafe { sys::o3d_io_write_point_cloud_to_memory(out, cloud.as_raw(), format.as_ptr(), &opts) })
}

/// Run a C encoder writing a new buffer, and own it.
pub(crate) fn new_buffer(f: impl FnOnce(*mut *mut sys::o3d_buffer_t) -> sys::o3d_status) -> Result<Buffer> {
    crate::util::adopt("buffer", f, |raw| Buffer { raw })
}

/// Encode `cloud` in `format` (e.g. `"ply"`) into a byte vector.
pub fn write_point_cloud_to_memory(cloud: &PointCloud, format: &str, options: &WriteOptions) -> Result<Vec<u8>> {
    write_point_cloud_to_buffer(cloud, format, options)?.to_vec()
}
