//! Small helpers shared by the handle wrappers: handle adoption, integer narrowing, optional arrays.
use std::mem::{size_of, MaybeUninit};
use std::ptr::{self, NonNull};

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};

/// Run a C constructor writing `*out`, and hand the new handle to `wrap`. A success without a
/// handle would be a library bug; it becomes an `Internal` error rather than a NULL wrapper.
pub(crate) fn adopt<H, T>(
    what: &str,
    f: impl FnOnce(*mut *mut H) -> sys::o3d_status,
    wrap: impl FnOnce(NonNull<H>) -> T,
) -> Result<T> {
    let mut out = ptr::null_mut();
    check(f(&mut out))?;
    NonNull::new(out)
        .map(wrap)
        .ok_or_else(|| Error::new(ErrorCode::Internal, format!("the library reported success but returned no {what}")))
}

/// A versioned C struct filled by its `*_init(ptr, struct_size)` (called as `init(ptr, size)`), so its
/// `struct_size` and defaults are the library's.
///
/// # Safety
/// All-zero bytes must be a valid `T` (numbers, nullable function pointers, raw pointers), and `init`
/// must write at most `size` bytes through its pointer.
pub(crate) unsafe fn init_struct<T>(init: impl FnOnce(*mut T, u32) -> sys::o3d_status) -> Result<T> {
    let mut raw = MaybeUninit::<T>::zeroed();
    check(init(raw.as_mut_ptr(), size_of::<T>() as u32))?;
    Ok(raw.assume_init())
}

/// `n` as the C API's `int32_t`, or an `InvalidArgument` error naming the parameter.
pub(crate) fn to_i32(n: usize, name: &str) -> Result<i32> {
    i32::try_from(n).map_err(|_| Error::new(ErrorCode::InvalidArgument, format!("{name} {n} is too large")))
}

/// NULL for `None`, else a pointer to the array.
pub(crate) fn opt_ptr<const N: usize>(v: &Option<[f64; N]>) -> *const f64 {
    v.as_ref().map_or(ptr::null(), |a| a.as_ptr())
}

/// Row-major 4x4 as the C API's 16 contiguous doubles.
pub(crate) fn mat4_ptr(m: &[[f64; 4]; 4]) -> *const f64 {
    m.as_ptr().cast()
}

/// Copy out a variable-length array with the query-then-copy convention (`out` NULL → count).
pub(crate) fn copy_out<T: Copy + Default>(
    mut f: impl FnMut(*mut T, usize, *mut usize) -> sys::o3d_status,
) -> Result<Vec<T>> {
    let mut n = 0usize;
    check(f(ptr::null_mut(), 0, &mut n))?;
    let mut out = vec![T::default(); n];
    let mut written = 0usize;
    check(f(out.as_mut_ptr(), n, &mut written))?;
    out.truncate(written);
    Ok(out)
}

/// An owned C handle type: the struct, `Send` + `Sync` (the C rule: concurrent calls on one handle
/// are safe when all take it `const`; `&self` methods make only `const` calls and every mutation
/// takes `&mut self`), `from_raw` / `as_raw` / `raw_mut`, `Drop`, a crate-private constructor
/// adopting what a C function writes and, given the C clone function, `try_clone` and `Clone`.
macro_rules! handle {
    ($(#[$doc:meta])* $name:ident($raw:ty, $what:literal), $adopt:ident, $destroy:path $(, $clone:path)?) => {
        $(#[$doc])*
        pub struct $name {
            raw: std::ptr::NonNull<$raw>,
        }

        // SAFETY: see the type's documentation.
        unsafe impl Send for $name {}
        unsafe impl Sync for $name {}

        /// Run a C function writing a new handle, and own it.
        pub(crate) fn $adopt(f: impl FnOnce(*mut *mut $raw) -> o3d_sys::o3d_status) -> crate::Result<$name> {
            crate::util::adopt($what, f, |raw| $name { raw })
        }

        impl $name {
            /// Take ownership of a raw handle (e.g. from `o3d-sys`).
            ///
            /// # Safety
            /// `raw` must be a valid handle of this type owned by the caller; it is destroyed on drop.
            pub unsafe fn from_raw(raw: std::ptr::NonNull<$raw>) -> $name {
                $name { raw }
            }

            /// The raw handle, still owned by `self`.
            pub fn as_raw(&self) -> *const $raw {
                self.raw.as_ptr()
            }

            #[allow(dead_code)]
            pub(crate) fn raw_mut(&mut self) -> *mut $raw {
                self.raw.as_ptr()
            }
        }

        impl Drop for $name {
            fn drop(&mut self) {
                // SAFETY: owned handle, destroyed once.
                unsafe { $destroy(self.raw.as_ptr()) }
            }
        }
        $(
            impl $name {
                /// Deep copy; [`Clone::clone`] panics where this returns `Err`.
                pub fn try_clone(&self) -> crate::Result<$name> {
                    // SAFETY: valid source handle.
                    $adopt(|out| unsafe { $clone(out, self.as_raw()) })
                }
            }

            impl Clone for $name {
                /// Deep copy. Panics if the library cannot copy (out of memory); see `try_clone`.
                fn clone(&self) -> Self {
                    self.try_clone().unwrap_or_else(|e| panic!("{} failed: {e}", stringify!($clone)))
                }
            }
        )?
    };
}
pub(crate) use handle;
