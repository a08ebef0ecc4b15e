//! Reading and writing (o3d.io): point clouds (PLY, PCD, XYZ, XYZN, XYZRGB, PTS), triangle meshes
//! (PLY, OBJ, STL, OFF, glTF/GLB), images (PNG, JPEG, PPM, PGM) and camera models (JSON, .log), to
//! files or memory; features (Open3D's binary layout) and pose graphs (Open3D's JSON).
//!
//! Formats are named as in Open3D (`"ply"`, `"pcd"`, ...); `"auto"` or `""` picks the format from
//! the file extension. Paths must be valid UTF-8 (anything else is an `InvalidArgument` error).
use std::ffi::CString;
use std::fmt;
use std::path::Path;
use std::ptr;
use std::slice;

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::{new_cloud, PointCloud};
use crate::util::{copy_out, handle, options};

pub use crate::feature::{read_feature, write_feature};
pub use crate::io_geometry::*;
pub use crate::posegraph::{read_pose_graph, write_pose_graph};

include!("generated/io.rs");

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

handle! {
    /// Bytes owned by the library (`o3d_buffer_t`), e.g. an encoded point cloud (immutable after
    /// creation: `Send` and `Sync`).
    Buffer(sys::o3d_buffer_t, "buffer"), new_buffer, sys::o3d_buffer_destroy
}

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
        copy_out::<u8>(|out, cap, n| unsafe { sys::o3d_buffer_get_data(out, cap, n, self.raw.as_ptr()) })
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

/// Encode `cloud` in `format` (e.g. `"ply"`) into a byte vector.
pub fn write_point_cloud_to_memory(cloud: &PointCloud, format: &str, options: &WriteOptions) -> Result<Vec<u8>> {
    write_point_cloud_to_buffer(cloud, format, options)?.to_vec()
}
