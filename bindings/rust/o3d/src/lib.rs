//! Safe Rust bindings for **o3d**, a library for 3D data processing (an Open3D replacement).
//!
//! Built only on the C API (`o3d-sys`, `libo3d.so.0`). Names follow Open3D:
//! [`PointCloud`] (`o3d.geometry.PointCloud`), [`TriangleMesh`], [`LineSet`], [`VoxelGrid`],
//! [`TetraMesh`], [`Octree`], [`OrientedBoundingBox`], [`Image`], [`RgbdImage`],
//! [`PinholeIntrinsic`] (`o3d.camera.PinholeCameraIntrinsic`), [`KDTreeFlann`],
//! [`io::read_point_cloud`], [`io::read_triangle_mesh`], [`registration::registration_icp`],
//! [`Feature`] and [`registration::compute_fpfh_feature`], global registration
//! ([`registration::registration_ransac_based_on_feature_matching`],
//! [`registration::registration_fgr_based_on_feature_matching`]), [`PoseGraph`] and
//! [`registration::global_optimization`], surface reconstruction
//! ([`TriangleMesh::create_from_point_cloud_poisson`], [`TriangleMesh::create_from_point_cloud_ball_pivoting`],
//! [`TriangleMesh::create_from_point_cloud_alpha_shape`]), [`keypoint::compute_iss_keypoints`],
//! and rendering without a display: [`OffscreenRenderer`]
//! (`o3d.visualization.rendering.OffscreenRenderer`) with [`RenderOption`] and [`RenderMaterial`],
//! and the viewer [`Visualizer`] (hidden windows render headless).
//!
//! * Every fallible call returns [`Result<T, Error>`](Error); the error carries the library's message.
//! * Handles are owned (`Drop` destroys them); views such as [`PointCloud::points`] are zero-copy
//!   slices borrowed from the handle, so the borrow checker enforces "valid until the next mutation".
//! * Threading (the C rule: concurrent calls on one handle are safe when all take it `const`): the
//!   handles are `Send` and `Sync`; every `&self` method calls only `const` C functions and every
//!   mutation takes `&mut self`.
//! * Callbacks (progress of ICP, RANSAC, FGR, global optimization and surface reconstruction; logging) are
//!   Rust closures run behind `catch_unwind`; a panic never crosses the C boundary.
//!
//! ```no_run
//! use o3d::{io, PointCloud, SearchParam};
//! let pcd = io::read_point_cloud("cloud_bin_0.pcd", "auto", &Default::default())?;
//! let mut down = pcd.voxel_down_sample(0.05)?;
//! down.estimate_normals(SearchParam::Hybrid { radius: 0.1, max_nn: 30 })?;
//! io::write_point_cloud("down.ply", &down, "auto", &Default::default())?;
//! # Ok::<(), o3d::Error>(())
//! ```
#![warn(missing_docs)]

use std::ffi::{c_char, c_void, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, RwLock};

pub use o3d_sys as sys;

mod array;
mod boundingbox;
pub mod camera;
pub mod color_map;
mod error;
mod feature;
mod halfedgemesh;
mod hull;
mod image;
pub mod integration;
pub mod io;
mod io_geometry;
mod kdtree;
pub mod keypoint;
mod lineset;
mod octree;
pub mod odometry;
mod panic;
mod pointcloud;
mod posegraph;
mod progress;
pub mod reconstruction;
pub mod registration;
mod registration_global;
mod rgbd;
mod selection;
mod surface_reconstruction;
mod tetramesh;
mod trianglemesh;
mod trianglemesh_ops;
mod trianglemesh_primitives;
mod trianglemesh_removal;
mod util;
pub mod visualization;
mod visualizer;
mod voxelgrid;

pub use boundingbox::{OrientedBoundingBox, OrientedBoundingEllipsoid};
pub use camera::{CameraTrajectory, IntrinsicPreset, PinholeCameraParameters, PinholeIntrinsic};
pub use error::{Error, ErrorCode, Result};
pub use feature::Feature;
pub use halfedgemesh::{HalfEdge, HalfEdgeTriangleMesh};
pub use image::{ConvertType, Image, ImageFilter, PixelType};
pub use kdtree::{KDTreeFlann, SearchResult, SearchResultRef};
pub use lineset::LineSet;
pub use octree::{Octree, OctreeLeaf, OctreeNodeInfo};
pub use pointcloud::{PlanarPatchOptions, PointCloud, SearchParam, VoxelDownSampleTrace};
pub use posegraph::{PoseGraph, PoseGraphEdge};
pub use registration_global::random_seed;
pub use rgbd::{DepthToCloudOptions, RgbdFormat, RgbdImage, RgbdOptions};
pub use surface_reconstruction::PoissonOptions;
pub use tetramesh::TetraMesh;
pub use trianglemesh::{MeshArray, TriangleMesh};
pub use trianglemesh_ops::{DeformAsRigidAsPossibleEnergy, FilterScope, SimplificationContraction, TriangleClusters};
pub use visualization::{
    ColorOption, Drawable, KeyAction, MeshShadeOption, MouseButton, OffscreenRenderer, RenderBackend, RenderMaterial,
    RenderOption, Shader, View, Visualizer,
};
pub use voxelgrid::{Voxel, VoxelGrid};

use error::check;
use util::{c_enum, options};

/// Library version string, e.g. `"0.1.0"`.
pub fn version() -> &'static str {
    // SAFETY: static storage, never NULL.
    unsafe { CStr::from_ptr(sys::o3d_version()) }.to_str().unwrap_or("?")
}

/// Library (major, minor, patch) version; major equals the SONAME number.
pub fn version_numbers() -> (i32, i32, i32) {
    // SAFETY: no arguments.
    unsafe { (sys::o3d_version_major(), sys::o3d_version_minor(), sys::o3d_version_patch()) }
}

include!("generated/lib.rs");

impl LogLevel {
    /// A level from the library; anything past `O3D_LOG_DEBUG` reads as `Debug`.
    fn from_level(level: i32) -> LogLevel {
        LogLevel::from_raw(level).unwrap_or(LogLevel::Debug)
    }
}

/// Show messages at `level` and more severe (default [`LogLevel::Warning`]).
pub fn set_verbosity_level(level: LogLevel) -> Result<()> {
    // SAFETY: plain value.
    check(unsafe { sys::o3d_set_verbosity_level(level.raw()) })
}

/// The current verbosity level.
pub fn get_verbosity_level() -> LogLevel {
    // SAFETY: no arguments.
    LogLevel::from_level(unsafe { sys::o3d_get_verbosity_level() })
}

/// Default thread count for parallel algorithms (0 restores the OpenMP default, the core count).
pub fn set_num_threads(num_threads: usize) -> Result<()> {
    let n = i32::try_from(num_threads)
        .map_err(|_| Error::new(ErrorCode::InvalidArgument, format!("num_threads {num_threads} is too large")))?;
    // SAFETY: plain value.
    check(unsafe { sys::o3d_set_num_threads(n) })
}

/// The thread count parallel algorithms use now (>= 1).
pub fn get_num_threads() -> usize {
    // SAFETY: no arguments.
    unsafe { sys::o3d_get_num_threads() }.max(1) as usize
}

type LogFn = dyn Fn(LogLevel, &str) + Send + Sync;

/// The installed log closure. The C side gets a trampoline and no user_data: the closure is looked
/// up here, so replacing it can never free one that another thread is running.
static LOG_CALLBACK: RwLock<Option<Arc<LogFn>>> = RwLock::new(None);

unsafe extern "C" fn log_trampoline(level: i32, message: *const c_char, _user_data: *mut c_void) {
    let callback = match LOG_CALLBACK.read() {
        Ok(guard) => guard.clone(),
        Err(poisoned) => poisoned.into_inner().clone(),
    };
    let Some(callback) = callback else { return };
    let text = if message.is_null() {
        std::borrow::Cow::Borrowed("")
    } else {
        // SAFETY: the library passes a NUL-terminated string valid for the call.
        unsafe { CStr::from_ptr(message) }.to_string_lossy()
    };
    // Log lines may come from worker threads and cannot report failure: a panicking log closure
    // is contained here and its payload dropped.
    if catch_unwind(AssertUnwindSafe(|| callback(LogLevel::from_level(level), &text))).is_err() {
        eprintln!("o3d: the log callback panicked; the panic was contained");
    }
}

/// Route the library's log lines to `callback` (global, for all threads); `None` restores the
/// default sink (stderr). The closure may be called from any thread, one line at a time.
pub fn set_log_callback<F>(callback: Option<F>) -> Result<()>
where
    F: Fn(LogLevel, &str) + Send + Sync + 'static,
{
    let new: Option<Arc<LogFn>> = callback.map(|f| Arc::new(f) as Arc<LogFn>);
    let install = new.is_some();
    *LOG_CALLBACK.write().unwrap_or_else(|p| p.into_inner()) = new;
    let trampoline: sys::o3d_log_callback = if install { Some(log_trampoline) } else { None };
    // SAFETY: the trampoline is a plain function; user_data is unused.
    check(unsafe { sys::o3d_set_log_callback(trampoline, std::ptr::null_mut()) })
}
