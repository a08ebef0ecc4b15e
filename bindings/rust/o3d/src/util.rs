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
