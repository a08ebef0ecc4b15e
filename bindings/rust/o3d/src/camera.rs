//! Pinhole cameras (o3d.camera): [`PinholeIntrinsic`] (a plain value) and [`CameraTrajectory`].
use std::fmt;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::util::{c_enum, handle, mat4_ptr};

/// o3d.camera.PinholeCameraIntrinsic: image size, focal lengths and principal point in pixels.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PinholeIntrinsic {
    /// Image width in pixels.
    pub width: i32,
    /// Image height in pixels.
    pub height: i32,
    /// Focal length along x, in pixels.
    pub fx: f64,
    /// Focal length along y, in pixels.
    pub fy: f64,
    /// Principal point x.
    pub cx: f64,
    /// Principal point y.
    pub cy: f64,
}

include!("generated/camera.rs");

impl PinholeIntrinsic {
    /// An intrinsic from its six values.
    pub fn new(width: i32, height: i32, fx: f64, fy: f64, cx: f64, cy: f64) -> PinholeIntrinsic {
        PinholeIntrinsic { width, height, fx, fy, cx, cy }
    }

    /// One of Open3D's presets (`o3d_pinhole_intrinsic_set_preset`).
    pub fn preset(preset: IntrinsicPreset) -> Result<PinholeIntrinsic> {
        let mut out = sys::o3d_pinhole_intrinsic_t::default();
        // SAFETY: writable struct.
        check(unsafe { sys::o3d_pinhole_intrinsic_set_preset(&mut out, preset.raw()) })?;
        Ok(PinholeIntrinsic::from_raw(out))
    }

    /// The 3x3 camera matrix, row-major.
    pub fn intrinsic_matrix(&self) -> [[f64; 3]; 3] {
        [[self.fx, 0.0, self.cx], [0.0, self.fy, self.cy], [0.0, 0.0, 1.0]]
    }

    /// The C struct.
    pub fn to_raw(self) -> sys::o3d_pinhole_intrinsic_t {
        sys::o3d_pinhole_intrinsic_t {
            width: self.width,
            height: self.height,
            fx: self.fx,
            fy: self.fy,
            cx: self.cx,
            cy: self.cy,
        }
    }

    /// From the C struct.
    pub fn from_raw(raw: sys::o3d_pinhole_intrinsic_t) -> PinholeIntrinsic {
        PinholeIntrinsic { width: raw.width, height: raw.height, fx: raw.fx, fy: raw.fy, cx: raw.cx, cy: raw.cy }
    }
}

/// One camera pose of a trajectory: intrinsic and row-major world-to-camera extrinsic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PinholeCameraParameters {
    /// The intrinsic.
    pub intrinsic: PinholeIntrinsic,
    /// Row-major 4x4 world-to-camera matrix.
    pub extrinsic: [[f64; 4]; 4],
}

handle! {
    /// o3d.camera.PinholeCameraTrajectory: a list of camera poses. Owns an `o3d_camera_trajectory_t`.
    CameraTrajectory(sys::o3d_camera_trajectory_t, "trajectory"), new_trajectory, sys::o3d_camera_trajectory_destroy
}

impl CameraTrajectory {
    /// A new empty trajectory.
    pub fn new() -> Result<CameraTrajectory> {
        // SAFETY: out-pointer.
        new_trajectory(|out| unsafe { sys::o3d_camera_trajectory_create(out) })
    }

    /// True when there are no poses.
    pub fn is_empty(&self) -> Result<bool> {
        Ok(self.len()? == 0)
    }

    /// Pose `index` (out of range → Err).
    pub fn get(&self, index: usize) -> Result<PinholeCameraParameters> {
        let mut intrinsic = sys::o3d_pinhole_intrinsic_t::default();
        let mut extrinsic = [[0.0f64; 4]; 4];
        // SAFETY: writable struct and 16 contiguous doubles.
        check(unsafe {
            sys::o3d_camera_trajectory_get(&mut intrinsic, extrinsic.as_mut_ptr().cast(), self.as_raw(), index)
        })?;
        Ok(PinholeCameraParameters { intrinsic: PinholeIntrinsic::from_raw(intrinsic), extrinsic })
    }

    /// Every pose, in order.
    pub fn parameters(&self) -> Result<Vec<PinholeCameraParameters>> {
        (0..self.len()?).map(|i| self.get(i)).collect()
    }

    /// Append a pose (the extrinsic's last row must be (0, 0, 0, 1)).
    pub fn push(&mut self, intrinsic: &PinholeIntrinsic, extrinsic: &[[f64; 4]; 4]) -> Result<()> {
        let raw = intrinsic.to_raw();
        // SAFETY: valid handle, struct and 16 doubles.
        check(unsafe { sys::o3d_camera_trajectory_append(self.raw.as_ptr(), &raw, mat4_ptr(extrinsic)) })
    }
}

impl fmt::Debug for CameraTrajectory {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CameraTrajectory").field("poses", &self.len().unwrap_or(0)).finish()
    }
}
