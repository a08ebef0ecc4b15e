//! Rendering without a display (o3d.visualization): [`RenderOption`], [`RenderMaterial`] and
//! [`OffscreenRenderer`] (rendering.OffscreenRenderer with its scene's add/remove/has/clear_geometry).
//! The camera and lighting model are the C header's (`o3d/visualization.h`).
//!
//! ```no_run
//! use o3d::visualization::{OffscreenRenderer, RenderBackend};
//! use o3d::TriangleMesh;
//! let mut renderer = OffscreenRenderer::new(640, 480, RenderBackend::Auto)?;
//! renderer.add_geometry("box", &TriangleMesh::create_box(1.0, 1.0, 1.0)?, &Default::default())?;
//! renderer.render_to_png("box.png")?;
//! # Ok::<(), o3d::Error>(())
//! ```
use std::ffi::c_char;
use std::fmt;
use std::path::Path;

use o3d_sys as sys;

use crate::camera::{PinholeCameraParameters, PinholeIntrinsic};
use crate::error::{check, Result};
use crate::image::Image;
use crate::io::{c_path, c_string};
use crate::lineset::LineSet;
use crate::pointcloud::PointCloud;
use crate::trianglemesh::TriangleMesh;
use crate::util::{c_enum, handle, mat4_ptr, options};
use crate::voxelgrid::VoxelGrid;

pub use crate::selection::{Axis, SelectionPolygonVolume};
pub use crate::visualizer::{KeyAction, KeyCallback, MouseButton, View, Visualizer};

include!("generated/visualization.rs");

impl RenderOption {
    /// RenderOption.load_from_json: the fields present in an Open3D RenderOption JSON file replace
    /// these; on error `self` is unchanged.
    pub fn load_from_json(&mut self, path: impl AsRef<Path>) -> Result<()> {
        let path = c_path(path.as_ref())?;
        let mut raw = self.to_raw()?;
        // SAFETY: a struct filled by its init and a NUL-terminated path.
        check(unsafe { sys::o3d_render_option_load_json(&mut raw, path.as_ptr()) })?;
        *self = RenderOption::from_raw(&raw)?;
        Ok(())
    }

    /// RenderOption.save_to_json, in Open3D's layout.
    pub fn save_to_json(&self, path: impl AsRef<Path>) -> Result<()> {
        let path = c_path(path.as_ref())?;
        let raw = self.to_raw()?;
        // SAFETY: a NUL-terminated path and a struct filled by its init.
        check(unsafe { sys::o3d_render_option_save_json(path.as_ptr(), &raw) })
    }
}


impl RenderMaterial {
    /// The defaults with `shader`, e.g. `RenderMaterial::with_shader(Shader::DefaultUnlit)`.
    pub fn with_shader(shader: Shader) -> RenderMaterial {
        RenderMaterial { shader, ..Default::default() }
    }
}

mod sealed {
    pub trait Sealed {}
}

/// A geometry an [`OffscreenRenderer`] or a [`Visualizer`] draws: [`PointCloud`], [`TriangleMesh`],
/// [`LineSet`] or [`VoxelGrid`] (sealed: each maps to its `o3d_offscreen_renderer_add_*` and
/// `o3d_visualizer_add_*`).
pub trait Drawable: sealed::Sealed {
    /// Call the C function adding a copy of `self`.
    ///
    /// # Safety
    /// `renderer` must be a valid renderer, `name` a NUL-terminated string and `material` a valid struct.
    #[doc(hidden)]
    unsafe fn add_to(
        &self,
        renderer: *mut sys::o3d_offscreen_renderer_t,
        name: *const c_char,
        material: *const sys::o3d_render_material_t,
    ) -> sys::o3d_status;
    /// Call the C function adding a copy of `self` to a visualizer.
    ///
    /// # Safety
    /// `vis` must be a valid visualizer and `name` a NUL-terminated string.
    #[doc(hidden)]
    unsafe fn show_in(&self, vis: *mut sys::o3d_visualizer_t, name: *const c_char, reset: i32) -> sys::o3d_status;
}

macro_rules! drawable {
    ($($ty:ty => $add:path, $show:path;)+) => {$(
        impl sealed::Sealed for $ty {}
        impl Drawable for $ty {
            unsafe fn add_to(
                &self,
                renderer: *mut sys::o3d_offscreen_renderer_t,
                name: *const c_char,
                material: *const sys::o3d_render_material_t,
            ) -> sys::o3d_status {
                // SAFETY: the caller's contract, and a valid geometry handle.
                unsafe { $add(renderer, name, self.as_raw(), material) }
            }
            unsafe fn show_in(&self, vis: *mut sys::o3d_visualizer_t, name: *const c_char, reset: i32) -> sys::o3d_status {
                // SAFETY: the caller's contract, and a valid geometry handle.
                unsafe { $show(vis, name, self.as_raw(), reset) }
            }
        }
    )+};
}
drawable! {
    PointCloud => sys::o3d_offscreen_renderer_add_pointcloud, sys::o3d_visualizer_add_pointcloud;
    TriangleMesh => sys::o3d_offscreen_renderer_add_trianglemesh, sys::o3d_visualizer_add_trianglemesh;
    LineSet => sys::o3d_offscreen_renderer_add_lineset, sys::o3d_visualizer_add_lineset;
    VoxelGrid => sys::o3d_offscreen_renderer_add_voxelgrid, sys::o3d_visualizer_add_voxelgrid;
}

handle! {
    /// rendering.OffscreenRenderer: draws copies of geometries into a `width` x `height` image without a
    /// display. Owns an `o3d_offscreen_renderer_t`. The library serializes calls on one renderer; its
    /// queries take `&mut self` as their C functions take a non-`const` handle. With the GLFW backend,
    /// create and use it on the main thread.
    OffscreenRenderer(sys::o3d_offscreen_renderer_t, "offscreen renderer"), new_renderer, sys::o3d_offscreen_renderer_destroy
}

impl OffscreenRenderer {
    /// A renderer of `width` x `height` pixels; `ErrorCode::Unsupported` when no OpenGL 3.3 context can
    /// be made (the message says what each backend answered).
    pub fn new(width: i32, height: i32, backend: RenderBackend) -> Result<OffscreenRenderer> {
        // SAFETY: out-pointer and plain values.
        new_renderer(|out| unsafe { sys::o3d_offscreen_renderer_create(out, width, height, backend.raw()) })
    }

    /// (width, height) in pixels.
    pub fn size(&self) -> Result<(i32, i32)> {
        let (mut w, mut h) = (0, 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { sys::o3d_offscreen_renderer_get_size(&mut w, &mut h, self.as_raw()) })?;
        Ok((w, h))
    }

    /// scene.add_geometry: add a copy of `geometry` under `name` (non-empty, not yet in the scene).
    pub fn add_geometry(&mut self, name: &str, geometry: &impl Drawable, material: &RenderMaterial) -> Result<()> {
        let name = c_string("name", name)?;
        let material = material.to_raw()?;
        // SAFETY: valid handles, a NUL-terminated name and a struct filled by its init.
        check(unsafe { geometry.add_to(self.raw_mut(), name.as_ptr(), &material) })
    }

    /// Replace the render option (`InvalidArgument` for a value out of range).
    pub fn set_render_option(&mut self, option: &RenderOption) -> Result<()> {
        let raw = option.to_raw()?;
        // SAFETY: valid handle and a struct filled by its init.
        check(unsafe { sys::o3d_offscreen_renderer_set_render_option(self.raw_mut(), &raw) })
    }

    /// The current render option.
    pub fn render_option(&mut self) -> Result<RenderOption> {
        let mut raw = RenderOption::raw_default()?;
        // SAFETY: valid handle and a struct whose struct_size its init set.
        check(unsafe { sys::o3d_offscreen_renderer_get_render_option(&mut raw, self.raw_mut()) })?;
        RenderOption::from_raw(&raw)
    }

    /// setup_camera(intrinsic, extrinsic): a pinhole camera of the renderer's size and a row-major
    /// world-to-camera rigid transform (the camera looks along +z, y down).
    pub fn setup_camera(&mut self, intrinsic: &PinholeIntrinsic, extrinsic: &[[f64; 4]; 4]) -> Result<()> {
        let k = intrinsic.to_raw();
        // SAFETY: valid handle, struct and 16 contiguous doubles.
        check(unsafe { sys::o3d_offscreen_renderer_setup_camera(self.raw_mut(), &k, mat4_ptr(extrinsic)) })
    }

    /// The camera the next render uses, as pinhole parameters: [`Self::setup_camera`] with them
    /// reproduces the image.
    pub fn camera(&mut self) -> Result<PinholeCameraParameters> {
        let mut k = sys::o3d_pinhole_intrinsic_t::default();
        let mut extrinsic = [[0.0f64; 4]; 4];
        // SAFETY: valid handle, writable struct and 16 contiguous doubles.
        check(unsafe {
            sys::o3d_offscreen_renderer_get_camera(&mut k, extrinsic.as_mut_ptr().cast(), self.raw_mut())
        })?;
        Ok(PinholeCameraParameters { intrinsic: PinholeIntrinsic::from_raw(k), extrinsic })
    }
}

impl fmt::Debug for OffscreenRenderer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("OffscreenRenderer")
            .field("size", &self.size().unwrap_or((0, 0)))
            .field("backend", &self.backend().ok())
            .finish()
    }
}
