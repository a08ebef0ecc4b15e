//! Per-point covariances of a [`PointCloud`] (o3d.geometry.PointCloud.covariances): one row-major
//! 3x3 matrix per point, kept through selection, append and transforms (see `pointcloud.h`).
use std::ptr;
use std::slice;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::pointcloud::{copy_out, PointCloud, SearchParam};

/// A row-major 3x3 matrix.
type Mat3 = [[f64; 3]; 3];

impl PointCloud {
    /// True when the cloud has one covariance per point.
    pub fn has_covariances(&self) -> Result<bool> {
        let mut v = 0;
        // SAFETY: valid handle and out-pointer.
        check(unsafe { sys::o3d_pointcloud_has_array(&mut v, self.as_raw(), O3D_POINTCLOUD_COVARIANCES) })?;
        Ok(v != 0)
    }

    /// Replace the covariances (copied once).
    pub fn set_covariances(&mut self, covariances: &[Mat3]) -> Result<()> {
        // SAFETY: covariances.len() matrices of 9 contiguous doubles; copied by the library.
        check(unsafe {
            sys::o3d_pointcloud_set_array(self.raw_mut(), O3D_POINTCLOUD_COVARIANCES, covariances.as_ptr().cast(), covariances.len())
        })
    }

    /// Zero-copy view of the covariances (empty when the cloud has none), borrowed from the cloud.
    pub fn covariances(&self) -> Result<&[Mat3]> {
        let (mut data, mut n) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_pointcloud_array_view(&mut data, &mut n, self.as_raw(), O3D_POINTCLOUD_COVARIANCES) })?;
        if data.is_null() || n == 0 {
            return Ok(&[]);
        }
        // SAFETY: n matrices of 9 doubles (align 8), valid until the next mutation (`&mut self`).
        Ok(unsafe { slice::from_raw_parts(data.cast::<Mat3>(), n) })
    }

    /// Copy of the covariances.
    pub fn covariances_to_vec(&self) -> Result<Vec<Mat3>> {
        // SAFETY: `out` has room for `cap` matrices or is NULL for the count query.
        copy_out::<Mat3>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_get_array(out.cast(), cap, n, self.as_raw(), O3D_POINTCLOUD_COVARIANCES)
        })
    }

    /// Covariance of each point's neighbourhood (divided by the neighbour count; fewer than 3
    /// neighbours give the identity, as Open3D). `SearchParam::default()` is Open3D's KNN 30.
    pub fn estimate_covariances(&mut self, param: SearchParam) -> Result<&mut Self> {
        let raw = param.to_raw()?;
        // SAFETY: valid handle and parameter struct.
        check(unsafe { sys::o3d_pointcloud_estimate_covariances(self.raw_mut(), &raw) })?;
        Ok(self)
    }
}
