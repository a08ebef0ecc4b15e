//! The viewer (o3d.visualization.Visualizer, VisualizerWithKeyCallback, VisualizerWithEditing and its
//! ViewControl) over `o3d/visualizer.h`. A hidden window (`visible = false`) renders through EGL, so
//! scripts and tests capture images and drive the keys and the mouse on a headless machine.
//!
//! Methods take `&self`: the handle stays on its thread (`Visualizer` is neither `Send` nor `Sync`) and
//! the library lets callbacks call back into it, so a shared borrow is all a call needs. Callbacks get a
//! `&Visualizer` of their own for the same handle; only registering one takes `&mut self`, because it
//! frees the closure it replaces, and a callback can never reach `&mut` of the owner.
//!
//! ```no_run
//! use o3d::visualization::Visualizer;
//! let mut vis = Visualizer::new()?;
//! vis.create_window("o3d", 640, 480, -1, -1, false)?;
//! vis.add_geometry("box", &o3d::TriangleMesh::create_box(1.0, 1.0, 1.0)?, true)?;
//! let mut frames = 0;
//! vis.register_animation_callback(move |v| {
//!     frames += 1; // a panic (from unwrap) ends run() with an Err
//!     v.rotate(10.0, 0.0).and_then(|()| if frames == 30 { v.close() } else { Ok(()) }).unwrap();
//!     true
//! })?;
//! vis.run()?; // 30 frames
//! # Ok::<(), o3d::Error>(())
//! ```
use std::any::Any;
use std::cell::RefCell;
use std::collections::HashMap;
use std::ffi::{c_void, CString};
use std::mem::ManuallyDrop;
use std::ops::ControlFlow;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::camera::{PinholeCameraParameters, PinholeIntrinsic};
use crate::error::{check, Result};
use crate::image::Image;
use crate::io::{c_path, c_string, new_buffer};
use crate::pointcloud::PointCloud;
use crate::progress::with_progress;
use crate::trianglemesh::TriangleMesh;
use crate::util::{adopt, c_enum, copy_out, mat4_ptr};
use crate::visualization::{Drawable, RenderOption};

include!("generated/visualizer.rs");

/// ViewControl's view: the eye looks at `lookat` from the direction `front`, `zoom` times the view box's
/// largest extent away in units of the field of view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// From lookat towards the eye.
    pub front: [f64; 3],
    /// The point looked at.
    pub lookat: [f64; 3],
    /// The image's up direction.
    pub up: [f64; 3],
    /// In [0.02, 2]; Open3D's default 0.7.
    pub zoom: f64,
}

type AnimationFn = dyn FnMut(&Visualizer) -> bool;
type KeyFn = dyn FnMut(&Visualizer, KeyAction, i32) -> bool;

/// A key callback: `f(vis, action, mods)` returns true when the geometry or the view changed.
pub trait KeyCallback: FnMut(&Visualizer, KeyAction, i32) -> bool + 'static {}
impl<F: FnMut(&Visualizer, KeyAction, i32) -> bool + 'static> KeyCallback for F {}

/// A registered closure. The library gets its address as `user_data`; the cell lives on the heap behind
/// a raw pointer, so no borrow of the `Visualizer` covers it while a callback runs, and the `RefCell`
/// turns a closure running again inside itself (a key callback sending its own key) into an error.
struct Slot<F: ?Sized>(NonNull<RefCell<Box<F>>>);

impl<F: ?Sized> Slot<F> {
    fn new(f: Box<F>) -> Self {
        Slot(NonNull::from(Box::leak(Box::new(RefCell::new(f)))))
    }
}

impl<F: ?Sized> Drop for Slot<F> {
    fn drop(&mut self) {
        // SAFETY: made by Box::leak in `new`, freed once; the library no longer calls it (replaced or
        // destroyed before the slot is dropped).
        drop(unsafe { Box::from_raw(self.0.as_ptr()) });
    }
}

/// o3d.visualization.Visualizer (with the key callbacks of VisualizerWithKeyCallback, and picking when
/// made by [`Visualizer::with_editing`]). Owns an `o3d_visualizer_t` and its callbacks; `Drop` closes
/// the window and frees both.
pub struct Visualizer {
    raw: NonNull<sys::o3d_visualizer_t>,
    animation: Option<Slot<AnimationFn>>,
    keys: HashMap<i32, Slot<KeyFn>>,
}

impl Drop for Visualizer {
    fn drop(&mut self) {
        // SAFETY: owned handle, destroyed once; the callback slots are freed after it (fields drop last).
        unsafe { sys::o3d_visualizer_destroy(self.raw.as_ptr()) }
    }
}

/// Run the closure `user_data` points at with a `&Visualizer` for `vis`. A panic (or a re-entry) becomes
/// the loop's error through o3d_visualizer_set_callback_error, so `run`/`send_*` return it as `Err`.
///
/// # Safety
/// `user_data` must be a live `Slot<F>`'s cell.
unsafe fn invoke<F: ?Sized>(
    vis: *mut sys::o3d_visualizer_t,
    user_data: *mut c_void,
    call: impl FnOnce(&mut F, &Visualizer) -> bool,
) -> i32 {
    let Some(raw) = NonNull::new(vis) else { return 0 };
    // The same handle, owning nothing and never dropped; shared, so the callback cannot register callbacks.
    let this = ManuallyDrop::new(Visualizer { raw, animation: None, keys: HashMap::new() });
    // SAFETY: the caller's contract.
    let cell = unsafe { &*user_data.cast::<RefCell<Box<F>>>() };
    let outcome = match cell.try_borrow_mut() {
        Ok(mut f) => catch_unwind(AssertUnwindSafe(|| call(&mut **f, &this))).map_err(|p| panic_text(&*p)),
        Err(_) => Err("a visualizer callback ran again from inside itself".to_string()),
    };
    match outcome {
        Ok(changed) => i32::from(changed),
        Err(message) => {
            let message = CString::new(message.replace('\0', " ")).unwrap_or_default();
            // SAFETY: valid handle and NUL-terminated message, from inside its callback.
            unsafe { sys::o3d_visualizer_set_callback_error(vis, message.as_ptr()) };
            0
        }
    }
}

/// What a getter of the last crop writes: a new handle wrapped by `wrap`, or None where it writes NULL (the
/// last crop was of the other kind, or nothing was cropped).
fn cropped<H, T>(
    f: impl FnOnce(*mut *mut H) -> sys::o3d_status,
    wrap: impl FnOnce(NonNull<H>) -> T,
) -> Result<Option<T>> {
    let mut out = ptr::null_mut();
    check(f(&mut out))?;
    Ok(NonNull::new(out).map(wrap))
}

fn panic_text(payload: &(dyn Any + Send)) -> String {
    let text = payload.downcast_ref::<&str>().copied().or_else(|| payload.downcast_ref::<String>().map(String::as_str));
    format!("a visualizer callback panicked: {}", text.unwrap_or("(no message)"))
}

unsafe extern "C" fn animation_trampoline(vis: *mut sys::o3d_visualizer_t, user_data: *mut c_void) -> i32 {
    // SAFETY: registered with a Slot<AnimationFn> that outlives the registration.
    unsafe { invoke::<AnimationFn>(vis, user_data, |f, v| f(v)) }
}

unsafe extern "C" fn key_trampoline(vis: *mut sys::o3d_visualizer_t, action: i32, mods: i32, ud: *mut c_void) -> i32 {
    // SAFETY: registered with a Slot<KeyFn> that outlives the registration.
    unsafe { invoke::<KeyFn>(vis, ud, |f, v| f(v, KeyAction::from_raw(action).expect("a key action"), mods)) }
}

type RegisterKey =
    unsafe extern "C" fn(*mut sys::o3d_visualizer_t, i32, sys::o3d_visualizer_key_callback, *mut c_void) -> i32;

impl Visualizer {
    /// A visualizer without a window yet.
    pub fn new() -> Result<Visualizer> {
        Self::create(false)
    }

    /// VisualizerWithEditing: Shift + left click picks a point of the first geometry added, Shift + right
    /// click drops the last pick ([`Self::picked_points`]).
    pub fn with_editing() -> Result<Visualizer> {
        Self::create(true)
    }

    fn create(editing: bool) -> Result<Visualizer> {
        let wrap = |raw| Visualizer { raw, animation: None, keys: HashMap::new() };
        // SAFETY: out-pointer and a flag.
        adopt("visualizer", |out| unsafe { sys::o3d_visualizer_create(out, i32::from(editing)) }, wrap)
    }

    fn raw(&self) -> *mut sys::o3d_visualizer_t {
        self.raw.as_ptr()
    }

    fn as_raw(&self) -> *const sys::o3d_visualizer_t {
        self.raw.as_ptr()
    }

    /// Replace the render option (`InvalidArgument` for a value out of range).
    pub fn set_render_option(&self, option: &RenderOption) -> Result<()> {
        // SAFETY: a valid handle and a struct that lives for the call.
        check(unsafe { sys::o3d_visualizer_set_render_option(self.raw(), &option.to_raw()?) })
    }

    /// ViewControl.set_front / set_lookat / set_up / set_zoom at once (on error the view is unchanged).
    pub fn set_view(&self, v: &View) -> Result<()> {
        let (front, lookat, up) = (v.front.as_ptr(), v.lookat.as_ptr(), v.up.as_ptr());
        // SAFETY: a valid handle and three arrays of 3 doubles.
        check(unsafe { sys::o3d_visualizer_view_set(self.raw(), front, lookat, up, v.zoom) })
    }

    /// ViewControl.convert_from_pinhole_camera_parameters: the same camera gives the same image (the
    /// window's size, centred principal point, fx = fy, field of view in [5, 90], rigid extrinsic).
    pub fn from_pinhole(&self, camera: &PinholeCameraParameters) -> Result<()> {
        let extrinsic = mat4_ptr(&camera.extrinsic);
        // SAFETY: a valid handle, a struct and 16 contiguous doubles that live for the call.
        check(unsafe { sys::o3d_visualizer_view_from_pinhole(self.raw(), &camera.intrinsic.to_raw(), extrinsic) })
    }

    /// add_geometry / update_geometry: a copy is drawn under `name`, replacing one of that name;
    /// `reset_bounding_box` grows the view box to take it in and resets the view.
    pub fn add_geometry(&self, name: &str, geometry: &impl Drawable, reset_bounding_box: bool) -> Result<()> {
        let name = c_string("name", name)?;
        // SAFETY: valid handles and a NUL-terminated name.
        check(unsafe { geometry.show_in(self.raw(), name.as_ptr(), i32::from(reset_bounding_box)) })
    }

    /// get_render_option (a copy).
    pub fn render_option(&self) -> Result<RenderOption> {
        let mut raw = RenderOption::raw_default()?;
        // SAFETY: a struct filled by its init and a valid handle.
        check(unsafe { sys::o3d_visualizer_get_render_option(&mut raw, self.raw()) })?;
        RenderOption::from_raw(&raw)
    }

    /// register_animation_callback: `f` runs once per loop of [`Self::run`] and returns true when the
    /// geometry or the view changed. Replaces the previous one.
    pub fn register_animation_callback(&mut self, f: impl FnMut(&Visualizer) -> bool + 'static) -> Result<()> {
        let slot = Slot::<AnimationFn>::new(Box::new(f));
        let (raw, user_data) = (self.raw(), slot.0.as_ptr().cast());
        // SAFETY: valid handle; the slot outlives the registration (kept until replaced or dropped).
        check(unsafe { sys::o3d_visualizer_register_animation_callback(raw, Some(animation_trampoline), user_data) })?;
        self.animation = Some(slot); // the old closure is freed only now that the library no longer has it
        Ok(())
    }

    /// register_key_callback: `f(vis, action, mods)` runs on press and repeat of `key` (GLFW's number:
    /// `'K' as i32`, `sys::O3D_KEY_*`) instead of o3d's binding; `mods`: `sys::O3D_KEY_MOD_*` bits.
    pub fn register_key_callback(&mut self, key: i32, f: impl KeyCallback) -> Result<()> {
        self.register_key(key, Box::new(f), sys::o3d_visualizer_register_key_callback)
    }

    /// register_key_action_callback: as [`Self::register_key_callback`], and also on release.
    pub fn register_key_action_callback(&mut self, key: i32, f: impl KeyCallback) -> Result<()> {
        self.register_key(key, Box::new(f), sys::o3d_visualizer_register_key_action_callback)
    }

    fn register_key(&mut self, key: i32, f: Box<KeyFn>, register: RegisterKey) -> Result<()> {
        let slot = Slot::new(f);
        // SAFETY: valid handle; the slot outlives the registration (kept until replaced or dropped).
        check(unsafe { register(self.raw(), key, Some(key_trampoline), slot.0.as_ptr().cast()) })?;
        self.keys.insert(key, slot);
        Ok(())
    }

    /// get_picked_points (editing): vertex indices of the first geometry added, in pick order.
    pub fn picked_points(&self) -> Result<Vec<usize>> {
        // SAFETY: `out` has room for `cap` indices or is NULL; valid handle.
        let picked = copy_out(|out, cap, n| unsafe { sys::o3d_visualizer_get_picked_points(out, cap, n, self.raw()) });
        Ok(picked?.into_iter().map(|i: i32| i as usize).collect())
    }

    /// get_cropped_geometry (editing): a copy of the last crop (key C) when it was of a point cloud.
    pub fn cropped_point_cloud(&self) -> Result<Option<PointCloud>> {
        // SAFETY: a valid handle; what it writes is a new cloud owned here.
        cropped(
            |out| unsafe { sys::o3d_visualizer_get_cropped_pointcloud(out, self.as_raw()) },
            |raw| unsafe { PointCloud::from_raw(raw) },
        )
    }

    /// get_cropped_geometry (editing): a copy of the last crop when it was of a triangle mesh.
    pub fn cropped_triangle_mesh(&self) -> Result<Option<TriangleMesh>> {
        // SAFETY: a valid handle; what it writes is a new mesh owned here.
        cropped(
            |out| unsafe { sys::o3d_visualizer_get_cropped_trianglemesh(out, self.as_raw()) },
            |raw| unsafe { TriangleMesh::from_raw(raw) },
        )
    }

    /// The view's front, lookat, up and zoom.
    pub fn view(&self) -> Result<View> {
        let mut v = View { front: [0.0; 3], lookat: [0.0; 3], up: [0.0; 3], zoom: 0.0 };
        let (front, lookat, up) = (v.front.as_mut_ptr(), v.lookat.as_mut_ptr(), v.up.as_mut_ptr());
        // SAFETY: three arrays of 3 doubles, a double, and a valid handle.
        check(unsafe { sys::o3d_visualizer_view_get(front, lookat, up, &mut v.zoom, self.raw()) }).map(|()| v)
    }

    /// ViewControl.convert_to_pinhole_camera_parameters.
    pub fn to_pinhole(&self) -> Result<PinholeCameraParameters> {
        let (mut k, mut extrinsic) = (sys::o3d_pinhole_intrinsic_t::default(), [[0.0f64; 4]; 4]);
        // SAFETY: a writable struct, 16 contiguous doubles and a valid handle.
        check(unsafe { sys::o3d_visualizer_view_to_pinhole(&mut k, extrinsic.as_mut_ptr().cast(), self.raw()) })?;
        Ok(PinholeCameraParameters { intrinsic: PinholeIntrinsic::from_raw(k), extrinsic })
    }

    /// The view as Open3D's ViewTrajectory JSON (what Ctrl+C copies).
    pub fn view_status(&self) -> Result<String> {
        // SAFETY: out-pointer and valid handle.
        let buffer = new_buffer(|out| unsafe { sys::o3d_visualizer_get_view_status(out, self.raw()) })?;
        Ok(String::from_utf8_lossy(buffer.as_bytes()?).into_owned())
    }

    /// Play a ViewTrajectory JSON file (draw_geometries_with_custom_animation), writing `image_%06d.png`
    /// (and with `capture_depth` `depth_%06d.png`) into `capture_dir` if given; `progress` runs after each
    /// frame and may break to stop (`ErrorCode::Cancelled`).
    pub fn play_view_trajectory(
        &self,
        path: impl AsRef<Path>,
        capture_dir: Option<&Path>,
        capture_depth: bool,
        progress: impl FnMut(f64) -> ControlFlow<()>,
    ) -> Result<()> {
        let (path, dir) = (c_path(path.as_ref())?, capture_dir.map(c_path).transpose()?);
        let (dir, depth) = (dir.as_ref().map_or(ptr::null(), |d| d.as_ptr()), i32::from(capture_depth));
        check(with_progress(progress, |cb, ud| {
            // SAFETY: valid handle, NUL-terminated paths (or NULL), the progress pair valid for the call.
            unsafe { sys::o3d_visualizer_play_view_trajectory(self.raw(), path.as_ptr(), dir, depth, cb, ud) }
        }))
    }
}
