//! RGB-D odometry (o3d.pipelines.odometry): [`compute_rgbd_odometry`], the rigid motion between two
//! RGB-D frames by dense photometric (color term) or photometric + geometric (hybrid term) alignment,
//! coarse to fine over image pyramids.
use std::ptr;

use o3d_sys as sys;

use crate::camera::PinholeIntrinsic;
use crate::error::{check, Result};
use crate::rgbd::RgbdImage;
use crate::util::{c_enum, mat4_ptr, options};

include!("generated/odometry.rs");

/// Open3D's OdometryOption: the C struct's scalars (generated [`OdometryOptions`]) plus the
/// iterations per pyramid level, which the C API takes as a separate array.
#[derive(Debug, Clone, PartialEq)]
pub struct OdometryOption {
    /// Depth thresholds (`o3d_odometry_options_init`'s defaults).
    pub scalars: OdometryOptions,
    /// Gauss-Newton iterations per level, coarsest first; its length is the number of levels (1..8).
    pub iteration_number_per_pyramid_level: Vec<i32>,
}

impl Default for OdometryOption {
    /// Open3D's defaults: the library's scalars and 20, 10, 5 iterations.
    fn default() -> Self {
        OdometryOption { scalars: OdometryOptions::default(), iteration_number_per_pyramid_level: vec![20, 10, 5] }
    }
}

/// What [`compute_rgbd_odometry`] returns: Open3D's (success, transformation, information).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OdometryResult {
    /// Whether a motion was found (false: the matrices are the identity).
    pub success: bool,
    /// Row-major 4x4, source camera -> target camera.
    pub transformation: [[f64; 4]; 4],
    /// The 6x6 information matrix of the point-to-point alignment at the result.
    pub information: [[f64; 6]; 6],
}

/// The motion taking `source` onto `target` (points of the source camera into the target camera's
/// frame), starting from `odo_init` (`None`: identity). The frames must be float intensity + float
/// depth of the intrinsic's size ([`RgbdImage::from_color_and_depth`]'s default). A pair that cannot
/// be aligned is not an error: `success` is false.
pub fn compute_rgbd_odometry(
    source: &RgbdImage,
    target: &RgbdImage,
    intrinsic: &PinholeIntrinsic,
    odo_init: Option<&[[f64; 4]; 4]>,
    jacobian: OdometryJacobian,
    option: &OdometryOption,
) -> Result<OdometryResult> {
    let intr = intrinsic.to_raw();
    let opts = option.scalars.to_raw()?;
    let levels = &option.iteration_number_per_pyramid_level;
    let mut out = OdometryResult { success: false, transformation: [[0.0; 4]; 4], information: [[0.0; 6]; 6] };
    let mut ok = 0;
    // SAFETY: valid handles and structs; 16 and 36 doubles out; NULL or 16 doubles in; `levels.len()`
    // ints (an empty Vec's dangling but non-NULL pointer makes 0 levels an error, not NULL's default).
    check(unsafe {
        sys::o3d_odometry_compute_rgbd(
            &mut ok,
            out.transformation.as_mut_ptr().cast(),
            out.information.as_mut_ptr().cast(),
            source.as_raw(),
            target.as_raw(),
            &intr,
            odo_init.map_or(ptr::null(), mat4_ptr),
            jacobian.raw(),
            levels.as_ptr(),
            levels.len(),
            &opts,
        )
    })?;
    out.success = ok != 0;
    Ok(out)
}
