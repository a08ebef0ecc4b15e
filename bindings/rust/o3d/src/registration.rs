//! Registration (o3d.pipelines.registration): ICP (point-to-point, point-to-plane, colored,
//! generalized, symmetric, with robust kernels), evaluation, information matrix; features and
//! global registration (RANSAC, FGR, [`registration_global`](crate::registration)); pose graphs
//! and global optimization. Transformations are row-major 4x4 (`[[f64; 4]; 4]`, `m[row][col]`).
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::PointCloud;
use crate::progress::progress_pair;
use crate::util::{c_enum, copy_out, options, CField};

pub use crate::feature::{
    compute_fpfh_feature, compute_fpfh_feature_with, correspondences_from_features, Feature, MatchOptions,
};
pub use crate::posegraph::{
    global_optimization, global_optimization_with_progress, GlobalOptimizationMethod, GlobalOptimizationOptions,
    GlobalOptimizationSummary, PoseGraph, PoseGraphEdge,
};
pub use crate::registration_global::*;

/// The 4x4 identity.
pub const IDENTITY: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

include!("generated/registration.rs");

impl Default for Estimation {
    /// The library's default (`o3d_icp_options_init`: point-to-point).
    fn default() -> Self {
        IcpOptions::default().estimation
    }
}

/// Robust kernel (M-estimator) weighting each residual `r` of point-to-plane, colored,
/// generalized and symmetric ICP; `k` is its scale (Open3D's `L2Loss()`, `TukeyLoss(k)`, ...).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RobustKernel {
    /// w = 1 (plain least squares).
    L2,
    /// w = 1 / |r|.
    L1,
    /// w = 1 if |r| <= k else k / |r|.
    Huber {
        /// Scale.
        k: f64,
    },
    /// w = 1 / (1 + (r / k)^2).
    Cauchy {
        /// Scale.
        k: f64,
    },
    /// Geman-McClure: w = k / (k + r^2)^2.
    GM {
        /// Scale.
        k: f64,
    },
    /// w = (1 - (r / k)^2)^2 if |r| <= k else 0.
    Tukey {
        /// Scale.
        k: f64,
    },
}

impl RobustKernel {
    /// (`O3D_KERNEL_*`, k); L2 and L1 pass the library's default k of 1 (unused).
    pub(crate) fn raw(self) -> (i32, f64) {
        match self {
            RobustKernel::L2 => (sys::O3D_KERNEL_L2, 1.0),
            RobustKernel::L1 => (sys::O3D_KERNEL_L1, 1.0),
            RobustKernel::Huber { k } => (sys::O3D_KERNEL_HUBER, k),
            RobustKernel::Cauchy { k } => (sys::O3D_KERNEL_CAUCHY, k),
            RobustKernel::GM { k } => (sys::O3D_KERNEL_GM, k),
            RobustKernel::Tukey { k } => (sys::O3D_KERNEL_TUKEY, k),
        }
    }

    pub(crate) fn from_raw(kernel: i32, k: f64) -> Result<RobustKernel> {
        Ok(match kernel {
            sys::O3D_KERNEL_L2 => RobustKernel::L2,
            sys::O3D_KERNEL_L1 => RobustKernel::L1,
            sys::O3D_KERNEL_HUBER => RobustKernel::Huber { k },
            sys::O3D_KERNEL_CAUCHY => RobustKernel::Cauchy { k },
            sys::O3D_KERNEL_GM => RobustKernel::GM { k },
            sys::O3D_KERNEL_TUKEY => RobustKernel::Tukey { k },
            other => return Err(Error::new(ErrorCode::Internal, format!("unknown robust kernel {other}"))),
        })
    }

    /// The weight this kernel gives to `residual` (Open3D's `RobustKernel.weight`). A k that is
    /// not finite and positive is an error.
    pub fn weight(&self, residual: f64) -> Result<f64> {
        let (kernel, k) = self.raw();
        let mut w = 0.0;
        // SAFETY: plain values and an out-pointer.
        check(unsafe { sys::o3d_robust_kernel_weight(&mut w, kernel, k, residual) })?;
        Ok(w)
    }
}

impl Default for RobustKernel {
    /// The library's default (`o3d_icp_options_init`: L2).
    fn default() -> Self {
        IcpOptions::default().kernel
    }
}

impl CField<(i32, f64)> for RobustKernel {
    fn to_c(&self, _: &str) -> Result<(i32, f64)> {
        Ok(self.raw())
    }
    fn from_c((kernel, k): (i32, f64)) -> Result<RobustKernel> {
        RobustKernel::from_raw(kernel, k)
    }
}


/// Result of a registration (o3d.pipelines.registration.RegistrationResult).
#[derive(Debug, Clone, PartialEq)]
pub struct RegistrationResult {
    /// Row-major 4x4 transformation moving the source onto the target.
    pub transformation: [[f64; 4]; 4],
    /// Inlier count / number of source points.
    pub fitness: f64,
    /// RMS distance of the inlier pairs.
    pub inlier_rmse: f64,
    /// Inlier pairs (source index, target index).
    pub correspondence_set: Vec<[i32; 2]>,
}

/// Owns an `o3d_registration_result_t` while it is read out.
struct RawResult(NonNull<sys::o3d_registration_result_t>);

impl Drop for RawResult {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once.
        unsafe { sys::o3d_registration_result_destroy(self.0.as_ptr()) }
    }
}

pub(crate) fn read_result(
    f: impl FnOnce(*mut *mut sys::o3d_registration_result_t) -> sys::o3d_status,
) -> Result<RegistrationResult> {
    let mut out = ptr::null_mut();
    check(f(&mut out))?;
    let raw = RawResult(
        NonNull::new(out)
            .ok_or_else(|| Error::new(ErrorCode::Internal, "the library reported success but returned no result"))?,
    );
    let h = raw.0.as_ptr();
    let mut r = RegistrationResult {
        transformation: [[0.0; 4]; 4],
        fitness: 0.0,
        inlier_rmse: 0.0,
        correspondence_set: Vec::new(),
    };
    // SAFETY: valid handle; out-pointers sized as the header says.
    unsafe {
        check(sys::o3d_registration_result_get_transformation(r.transformation.as_mut_ptr().cast(), h))?;
        check(sys::o3d_registration_result_get_fitness(&mut r.fitness, h))?;
        check(sys::o3d_registration_result_get_inlier_rmse(&mut r.inlier_rmse, h))?;
    }
    // SAFETY: `out` has room for `cap` pairs of int32, or is NULL.
    r.correspondence_set = copy_out::<[i32; 2]>(|out, cap, n| unsafe {
        sys::o3d_registration_result_get_correspondence_set(out.cast(), cap, n, h)
    })?;
    Ok(r)
}

progress_pair! {
    /// Iterative closest point from `source` onto `target`, starting at `init`.
    /// Pairs farther apart than `max_correspondence_distance` are ignored.
    pub fn registration_icp;
    /// As [`registration_icp`], calling `progress(iteration / max_iteration)` after each iteration on
    /// this thread. Return `ControlFlow::Break(())` to stop: the call then fails with
    /// [`ErrorCode::Cancelled`]. A panic in `progress` cancels the call and resumes after it.
    pub fn registration_icp_with_progress(
        source: &PointCloud,
        target: &PointCloud,
        max_correspondence_distance: f64,
        init: &[[f64; 4]; 4],
        options: &IcpOptions,
    ) -> Result<RegistrationResult>;
    |callback, user_data| {
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        // SAFETY: valid handles, 16 doubles; user_data outlives the call.
        read_result(|out| unsafe {
            sys::o3d_register_icp(
                out,
                source.as_raw(),
                target.as_raw(),
                max_correspondence_distance,
                init.as_ptr().cast(),
                &opts,
            )
        })
    }
}

/// ICP with `estimation` in place of `options.estimation`.
fn icp_as(
    estimation: Estimation,
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    init: &[[f64; 4]; 4],
    options: &IcpOptions,
) -> Result<RegistrationResult> {
    let options = IcpOptions { estimation, ..*options };
    registration_icp(source, target, max_correspondence_distance, init, &options)
}

/// Colored ICP (Park et al. 2017; `options.estimation` is ignored): both clouds need colors, the
/// target normals. @see o3d.pipelines.registration.registration_colored_icp
pub fn registration_colored_icp(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    init: &[[f64; 4]; 4],
    options: &IcpOptions,
) -> Result<RegistrationResult> {
    icp_as(Estimation::Colored, source, target, max_correspondence_distance, init, options)
}

/// Generalized ICP (Segal et al. 2009; `options.estimation` is ignored).
/// @see o3d.pipelines.registration.registration_generalized_icp
pub fn registration_generalized_icp(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    init: &[[f64; 4]; 4],
    options: &IcpOptions,
) -> Result<RegistrationResult> {
    icp_as(Estimation::Generalized, source, target, max_correspondence_distance, init, options)
}

/// Symmetric point-to-plane ICP (Rusinkiewicz 2019; `options.estimation` is ignored): both clouds
/// need normals. @see o3d.pipelines.registration.registration_symmetric_icp
pub fn registration_symmetric_icp(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    init: &[[f64; 4]; 4],
    options: &IcpOptions,
) -> Result<RegistrationResult> {
    icp_as(Estimation::Symmetric, source, target, max_correspondence_distance, init, options)
}

/// Fitness, inlier RMSE and correspondences of `source` moved by `transformation`.
pub fn evaluate_registration(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    transformation: &[[f64; 4]; 4],
) -> Result<RegistrationResult> {
    // SAFETY: valid handles and 16 doubles.
    read_result(|out| unsafe {
        sys::o3d_evaluate_registration(
            out,
            source.as_raw(),
            target.as_raw(),
            max_correspondence_distance,
            transformation.as_ptr().cast(),
        )
    })
}

/// The 6x6 information matrix of the correspondences under `transformation`.
pub fn get_information_matrix_from_point_clouds(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    transformation: &[[f64; 4]; 4],
) -> Result<[[f64; 6]; 6]> {
    let mut out = [[0.0; 6]; 6];
    // SAFETY: valid handles, 16 doubles in, room for 36 doubles out.
    check(unsafe {
        sys::o3d_get_information_matrix_from_point_clouds(
            out.as_mut_ptr().cast(),
            source.as_raw(),
            target.as_raw(),
            max_correspondence_distance,
            transformation.as_ptr().cast(),
        )
    })?;
    Ok(out)
}
