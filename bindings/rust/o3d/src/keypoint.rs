//! Keypoint detection (o3d.geometry.keypoint): Intrinsic Shape Signatures. `IssOptions` is generated from
//! the C header.
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::PointCloud;
use crate::util::options;

include!("generated/keypoint.rs");

/// Intrinsic Shape Signature keypoints (Zhong 2009): points whose neighbourhood scatter has three distinct
/// eigenvalues and the largest smallest eigenvalue within `non_max_radius`. Returns the keypoints (with
/// their normals and colors) and their indices in `cloud`, ascending.
/// @see o3d.geometry.keypoint.compute_iss_keypoints
pub fn compute_iss_keypoints(cloud: &PointCloud, options: &IssOptions) -> Result<(PointCloud, Vec<i32>)> {
    let opts = options.to_raw()?;
    // A keypoint is an input point, so the cloud's size is room enough for the indices.
    let mut indices = vec![0i32; cloud.try_len()?];
    let (mut raw, mut n) = (ptr::null_mut(), 0usize);
    // SAFETY: a valid handle; `indices` has room for its length in ints; out-pointers and options valid.
    let status = unsafe {
        sys::o3d_pointcloud_compute_iss_keypoints(
            &mut raw,
            indices.as_mut_ptr(),
            indices.len(),
            &mut n,
            cloud.as_raw(),
            &opts,
        )
    };
    // Own whatever was written before looking at the status, so nothing leaks.
    // SAFETY: a handle written by the library belongs to the caller.
    let keypoints = NonNull::new(raw).map(|raw| unsafe { PointCloud::from_raw(raw) });
    check(status)?;
    let keypoints = keypoints
        .ok_or_else(|| Error::new(ErrorCode::Internal, "the library reported success but returned no cloud"))?;
    indices.truncate(n.min(indices.len()));
    Ok((keypoints, indices))
}

impl PointCloud {
    /// The cloud's ISS keypoints and their indices: [`compute_iss_keypoints`] on `self`.
    pub fn compute_iss_keypoints(&self, options: &IssOptions) -> Result<(PointCloud, Vec<i32>)> {
        compute_iss_keypoints(self, options)
    }
}
