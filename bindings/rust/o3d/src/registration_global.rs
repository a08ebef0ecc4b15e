//! Global registration (re-exported by [`crate::registration`]): correspondence checkers, RANSAC
//! over feature matches or given correspondences, Fast Global Registration.
use std::ptr;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::feature::Feature;
use crate::pointcloud::PointCloud;
use crate::progress::progress_pair;
use crate::registration::{read_result, Estimation, RegistrationResult};
use crate::util::{init_struct, mat4_ptr, options};

/// A test that prunes RANSAC hypotheses early (Open3D's `CorrespondenceChecker*`). The threshold
/// must be finite and positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CorrespondenceChecker {
    /// CorrespondenceCheckerBasedOnEdgeLength(similarity_threshold in (0, 1], Open3D uses 0.9):
    /// the lengths of every pair of edges between the drawn points must agree within this ratio.
    EdgeLength(f64),
    /// CorrespondenceCheckerBasedOnDistance(distance_threshold): every moved source point lies
    /// within this distance of its target.
    Distance(f64),
    /// CorrespondenceCheckerBasedOnNormal(normal_angle_threshold, radians): moved source normals
    /// and target normals differ by at most this angle (both clouds need normals).
    Normal(f64),
}

impl CorrespondenceChecker {
    fn kind(self) -> (i32, f64) {
        match self {
            CorrespondenceChecker::EdgeLength(t) => (sys::O3D_CHECKER_EDGE_LENGTH, t),
            CorrespondenceChecker::Distance(t) => (sys::O3D_CHECKER_DISTANCE, t),
            CorrespondenceChecker::Normal(t) => (sys::O3D_CHECKER_NORMAL, t),
        }
    }

    fn raw_default(kind: i32) -> Result<sys::o3d_correspondence_checker_t> {
        // SAFETY: o3d_correspondence_checker_t is plain numbers and nullable pointers; o3d_correspondence_checker_init is its init.
        unsafe { init_struct(|p, n| sys::o3d_correspondence_checker_init(p, n, kind)) }
    }

    pub(crate) fn to_raw(self) -> Result<sys::o3d_correspondence_checker_t> {
        let (kind, threshold) = self.kind();
        let mut raw = CorrespondenceChecker::raw_default(kind)?;
        raw.threshold = threshold;
        Ok(raw)
    }

    /// The library's default checker of each kind (`o3d_correspondence_checker_init`): edge
    /// length 0.9, distance 0.075, normal 30 degrees.
    pub fn library_defaults() -> Result<[CorrespondenceChecker; 3]> {
        let t = |kind| CorrespondenceChecker::raw_default(kind).map(|r| r.threshold);
        Ok([
            CorrespondenceChecker::EdgeLength(t(sys::O3D_CHECKER_EDGE_LENGTH)?),
            CorrespondenceChecker::Distance(t(sys::O3D_CHECKER_DISTANCE)?),
            CorrespondenceChecker::Normal(t(sys::O3D_CHECKER_NORMAL)?),
        ])
    }

    /// Does the hypothesis pass? `corres` are (source, target) index pairs; `transformation`
    /// moves the source. @see CorrespondenceChecker.Check
    pub fn check(
        &self,
        source: &PointCloud,
        target: &PointCloud,
        corres: &[[i32; 2]],
        transformation: &[[f64; 4]; 4],
    ) -> Result<bool> {
        let raw = self.to_raw()?;
        let mut passed = 0;
        // SAFETY: valid handles; corres.len() pairs of int32; 16 doubles.
        check(unsafe {
            sys::o3d_correspondence_checker_check(
                &mut passed,
                &raw,
                source.as_raw(),
                target.as_raw(),
                corres.as_ptr().cast(),
                corres.len(),
                mat4_ptr(transformation),
            )
        })?;
        Ok(passed != 0)
    }
}

fn raw_checkers(checkers: &[CorrespondenceChecker]) -> Result<Vec<sys::o3d_correspondence_checker_t>> {
    checkers.iter().map(|c| c.to_raw()).collect()
}

fn checkers_ptr(raw: &[sys::o3d_correspondence_checker_t]) -> *const sys::o3d_correspondence_checker_t {
    if raw.is_empty() {
        ptr::null()
    } else {
        raw.as_ptr()
    }
}

include!("generated/registration_global.rs");

progress_pair! {
    /// RANSAC over feature correspondences (the nearest target descriptor of each source descriptor):
    /// each hypothesis fits `ransac_n` drawn pairs, must pass every checker, and is scored by the
    /// share of pairs within `max_correspondence_distance` after the move.
    /// @see o3d.pipelines.registration.registration_ransac_based_on_feature_matching
    pub fn registration_ransac_based_on_feature_matching;
    /// As [`registration_ransac_based_on_feature_matching`], reporting the share of `max_iteration`
    /// done to `progress` on this thread (it jumps to 1 when confident). Return
    /// `ControlFlow::Break(())` to stop with [`crate::ErrorCode::Cancelled`]; a panic cancels and resumes.
    pub fn registration_ransac_based_on_feature_matching_with_progress(
        source: &PointCloud,
        target: &PointCloud,
        source_feature: &Feature,
        target_feature: &Feature,
        max_correspondence_distance: f64,
        checkers: &[CorrespondenceChecker],
        options: &RansacOptions,
    ) -> Result<RegistrationResult>;
    |callback, user_data| {
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        let raw = raw_checkers(checkers)?;
        // SAFETY: valid handles; raw.len() checkers (NULL when none); user_data outlives the call.
        read_result(|out| unsafe {
            sys::o3d_register_ransac_based_on_feature_matching(
                out,
                source.as_raw(),
                target.as_raw(),
                source_feature.as_raw(),
                target_feature.as_raw(),
                max_correspondence_distance,
                checkers_ptr(&raw),
                raw.len(),
                &opts,
            )
        })
    }
}

progress_pair! {
    /// RANSAC over given (source, target) pairs (`options.mutual_filter` is ignored).
    /// @see o3d.pipelines.registration.registration_ransac_based_on_correspondence
    pub fn registration_ransac_based_on_correspondence;
    /// As [`registration_ransac_based_on_correspondence`] with a progress closure (see
    /// [`registration_ransac_based_on_feature_matching_with_progress`]).
    pub fn registration_ransac_based_on_correspondence_with_progress(
        source: &PointCloud,
        target: &PointCloud,
        corres: &[[i32; 2]],
        max_correspondence_distance: f64,
        checkers: &[CorrespondenceChecker],
        options: &RansacOptions,
    ) -> Result<RegistrationResult>;
    |callback, user_data| {
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        let raw = raw_checkers(checkers)?;
        // SAFETY: valid handles; corres.len() pairs; raw.len() checkers; user_data outlives the call.
        read_result(|out| unsafe {
            sys::o3d_register_ransac_based_on_correspondence(
                out,
                source.as_raw(),
                target.as_raw(),
                corres.as_ptr().cast(),
                corres.len(),
                max_correspondence_distance,
                checkers_ptr(&raw),
                raw.len(),
                &opts,
            )
        })
    }
}


progress_pair! {
    /// Fast Global Registration (Zhou, Park, Koltun 2016) on mutual feature matches.
    /// @see o3d.pipelines.registration.registration_fgr_based_on_feature_matching
    pub fn registration_fgr_based_on_feature_matching;
    /// As [`registration_fgr_based_on_feature_matching`], reporting the share of `iteration_number`
    /// done to `progress` on this thread; `ControlFlow::Break(())` stops with [`crate::ErrorCode::Cancelled`].
    pub fn registration_fgr_based_on_feature_matching_with_progress(
        source: &PointCloud,
        target: &PointCloud,
        source_feature: &Feature,
        target_feature: &Feature,
        options: &FgrOptions,
    ) -> Result<RegistrationResult>;
    |callback, user_data| {
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        // SAFETY: valid handles; user_data outlives the call.
        read_result(|out| unsafe {
            sys::o3d_register_fgr_based_on_feature_matching(
                out,
                source.as_raw(),
                target.as_raw(),
                source_feature.as_raw(),
                target_feature.as_raw(),
                &opts,
            )
        })
    }
}

progress_pair! {
    /// Fast Global Registration on given (source, target) pairs.
    /// @see o3d.pipelines.registration.registration_fgr_based_on_correspondence
    pub fn registration_fgr_based_on_correspondence;
    /// As [`registration_fgr_based_on_correspondence`] with a progress closure.
    pub fn registration_fgr_based_on_correspondence_with_progress(
        source: &PointCloud,
        target: &PointCloud,
        corres: &[[i32; 2]],
        options: &FgrOptions,
    ) -> Result<RegistrationResult>;
    |callback, user_data| {
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        // SAFETY: valid handles; corres.len() pairs of int32; user_data outlives the call.
        read_result(|out| unsafe {
            sys::o3d_register_fgr_based_on_correspondence(
                out,
                source.as_raw(),
                target.as_raw(),
                corres.as_ptr().cast(),
                corres.len(),
                &opts,
            )
        })
    }
}

/// Seed the global generator that RANSAC and FGR draw from when given no seed (without it the
/// generator starts from a random device). @see o3d.utility.random.seed
pub fn random_seed(seed: u64) -> Result<()> {
    // SAFETY: plain value.
    check(unsafe { sys::o3d_random_seed(seed) })
}
