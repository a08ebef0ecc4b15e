//! Registration (o3d.pipelines.registration): ICP, evaluation, information matrix.
//! Transformations are row-major 4x4 (`[[f64; 4]; 4]`, `m[row][col]`).
use std::ffi::c_void;
use std::mem::{size_of, MaybeUninit};
use std::ops::ControlFlow;
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::pointcloud::{copy_out, PointCloud};

/// The 4x4 identity.
pub const IDENTITY: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

/// Transformation estimation method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Estimation {
    /// TransformationEstimationPointToPoint (with optional scaling, see [`IcpOptions::with_scaling`]).
    #[default]
    PointToPoint,
    /// TransformationEstimationPointToPlane (the target needs normals).
    PointToPlane,
}

/// ICP options: estimation method and ICPConvergenceCriteria. `Default` is Open3D's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IcpOptions {
    /// Estimation method (default point-to-point).
    pub estimation: Estimation,
    /// Point-to-point only: also estimate a scale (default false).
    pub with_scaling: bool,
    /// Stop when fitness changes less than this (default 1e-6).
    pub relative_fitness: f64,
    /// Stop when inlier RMSE changes less than this (default 1e-6).
    pub relative_rmse: f64,
    /// Iteration limit (default 30).
    pub max_iteration: usize,
    /// Threads; 0 = the library default (default 0).
    pub num_threads: usize,
}

impl Default for IcpOptions {
    fn default() -> Self {
        IcpOptions {
            estimation: Estimation::PointToPoint,
            with_scaling: false,
            relative_fitness: 1e-6,
            relative_rmse: 1e-6,
            max_iteration: 30,
            num_threads: 0,
        }
    }
}

fn to_i32(what: &str, n: usize) -> Result<i32> {
    i32::try_from(n).map_err(|_| Error::new(ErrorCode::InvalidArgument, format!("{what} {n} is too large")))
}

impl IcpOptions {
    /// The library's defaults (`o3d_icp_options_init`); equal to `Default` for a matching library.
    pub fn library_defaults() -> Result<IcpOptions> {
        let raw = raw_icp_options()?;
        Ok(IcpOptions {
            estimation: if raw.estimation == sys::O3D_ESTIMATION_POINT_TO_PLANE {
                Estimation::PointToPlane
            } else {
                Estimation::PointToPoint
            },
            with_scaling: raw.with_scaling != 0,
            relative_fitness: raw.relative_fitness,
            relative_rmse: raw.relative_rmse,
            max_iteration: raw.max_iteration.max(0) as usize,
            num_threads: raw.num_threads.max(0) as usize,
        })
    }

    fn to_raw(self) -> Result<sys::o3d_icp_options_t> {
        let mut raw = raw_icp_options()?;
        raw.estimation = match self.estimation {
            Estimation::PointToPoint => sys::O3D_ESTIMATION_POINT_TO_POINT,
            Estimation::PointToPlane => sys::O3D_ESTIMATION_POINT_TO_PLANE,
        };
        raw.with_scaling = self.with_scaling as i32;
        raw.relative_fitness = self.relative_fitness;
        raw.relative_rmse = self.relative_rmse;
        raw.max_iteration = to_i32("max_iteration", self.max_iteration)?;
        raw.num_threads = to_i32("num_threads", self.num_threads)?;
        Ok(raw)
    }
}

fn raw_icp_options() -> Result<sys::o3d_icp_options_t> {
    let mut raw = MaybeUninit::<sys::o3d_icp_options_t>::zeroed();
    // SAFETY: writable struct of the size passed.
    check(unsafe { sys::o3d_icp_options_init(raw.as_mut_ptr(), size_of::<sys::o3d_icp_options_t>() as u32) })?;
    // SAFETY: zeroed (progress = None, user_data = NULL are valid), then filled by init.
    Ok(unsafe { raw.assume_init() })
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

fn read_result(
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
        check(sys::o3d_registration_result_get_transformation(h, r.transformation.as_mut_ptr().cast()))?;
        check(sys::o3d_registration_result_get_fitness(h, &mut r.fitness))?;
        check(sys::o3d_registration_result_get_inlier_rmse(h, &mut r.inlier_rmse))?;
    }
    // SAFETY: `out` has room for `cap` pairs of int32, or is NULL.
    r.correspondence_set = copy_out::<[i32; 2]>(|out, cap, n| unsafe {
        sys::o3d_registration_result_get_correspondence_set(h, out.cast(), cap, n)
    })?;
    Ok(r)
}

type ProgressFn<'a> = dyn FnMut(f64) -> ControlFlow<()> + 'a;

unsafe extern "C" fn progress_trampoline(fraction: f64, user_data: *mut c_void) -> i32 {
    // SAFETY: user_data is the `&mut &mut ProgressFn` set up by registration_icp_with_progress,
    // alive for the whole call; the callback runs on the calling thread.
    let callback = unsafe { &mut *(user_data as *mut &mut ProgressFn<'_>) };
    match crate::panic::wrap(|| callback(fraction)) {
        Some(ControlFlow::Continue(())) => 0,
        Some(ControlFlow::Break(())) => 1,
        None => 1, // panicked: cancel; the panic resumes when the call returns
    }
}

/// Iterative closest point from `source` onto `target`, starting at `init`.
/// Pairs farther apart than `max_correspondence_distance` are ignored.
pub fn registration_icp(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    init: &[[f64; 4]; 4],
    options: &IcpOptions,
) -> Result<RegistrationResult> {
    let opts = options.to_raw()?;
    // SAFETY: valid handles, 16 doubles, valid options without callback.
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

/// As [`registration_icp`], calling `progress(iteration / max_iteration)` after each iteration on
/// this thread. Return `ControlFlow::Break(())` to stop: the call then fails with
/// [`ErrorCode::Cancelled`]. A panic in `progress` cancels the call and resumes after it.
pub fn registration_icp_with_progress<F>(
    source: &PointCloud,
    target: &PointCloud,
    max_correspondence_distance: f64,
    init: &[[f64; 4]; 4],
    options: &IcpOptions,
    mut progress: F,
) -> Result<RegistrationResult>
where
    F: FnMut(f64) -> ControlFlow<()>,
{
    let mut opts = options.to_raw()?;
    let mut callback: &mut ProgressFn<'_> = &mut progress;
    opts.progress = Some(progress_trampoline);
    opts.user_data = &mut callback as *mut &mut ProgressFn<'_> as *mut c_void;
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
            source.as_raw(),
            target.as_raw(),
            max_correspondence_distance,
            transformation.as_ptr().cast(),
            out.as_mut_ptr().cast(),
        )
    })?;
    Ok(out)
}
