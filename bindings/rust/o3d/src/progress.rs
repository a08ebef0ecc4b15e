//! Progress closures for long calls (ICP, RANSAC, FGR, global optimization): the library gets a
//! trampoline and a pointer to the closure; the closure runs on the calling thread behind
//! `catch_unwind`, and returning `ControlFlow::Break(())` (or panicking) cancels the call.
use std::ffi::c_void;
use std::ops::ControlFlow;

use o3d_sys as sys;

type ProgressFn<'a> = dyn FnMut(f64) -> ControlFlow<()> + 'a;

unsafe extern "C" fn progress_trampoline(fraction: f64, user_data: *mut c_void) -> i32 {
    // SAFETY: user_data is the `&mut &mut ProgressFn` set up by `with_progress`, alive for the
    // whole call; the library calls progress on the calling thread only.
    let callback = unsafe { &mut *(user_data as *mut &mut ProgressFn<'_>) };
    match crate::panic::wrap(|| callback(fraction)) {
        Some(ControlFlow::Continue(())) => 0,
        Some(ControlFlow::Break(())) => 1,
        None => 1, // panicked: cancel; the panic resumes when the call returns (error::check)
    }
}

/// Run `call(progress, user_data)` with `progress` wired to the C callback fields. The pointers
/// are valid only during `call`; the result must be passed through `error::check`, which resumes
/// a panic the closure raised.
pub(crate) fn with_progress<F, R>(mut progress: F, call: impl FnOnce(sys::o3d_progress_callback, *mut c_void) -> R) -> R
where
    F: FnMut(f64) -> ControlFlow<()>,
{
    let mut callback: &mut ProgressFn<'_> = &mut progress;
    let user_data = &mut callback as *mut &mut ProgressFn<'_> as *mut c_void;
    call(Some(progress_trampoline), user_data)
}

/// A long call and its `_with_progress` twin from one body: `|callback, user_data| body` runs with
/// the C progress fields NULL in the plain function, and wired to the closure (as
/// [`with_progress`]) in the twin, which takes a trailing `progress: F`.
macro_rules! progress_pair {
    (
        $(#[$doc:meta])* pub fn $plain:ident;
        $(#[$pdoc:meta])* pub fn $with:ident($($arg:ident: $ty:ty),+ $(,)?) -> $ret:ty;
        |$cb:ident, $ud:ident| $body:expr
    ) => {
        $(#[$doc])*
        #[allow(clippy::too_many_arguments)]
        pub fn $plain($($arg: $ty),+) -> $ret {
            let run = |$cb: o3d_sys::o3d_progress_callback, $ud: *mut std::ffi::c_void| -> $ret { $body };
            run(None, std::ptr::null_mut())
        }

        $(#[$pdoc])*
        #[allow(clippy::too_many_arguments)]
        pub fn $with<F>($($arg: $ty),+, progress: F) -> $ret
        where
            F: FnMut(f64) -> std::ops::ControlFlow<()>,
        {
            crate::progress::with_progress(progress, |$cb, $ud| -> $ret { $body })
        }
    };
}
pub(crate) use progress_pair;
