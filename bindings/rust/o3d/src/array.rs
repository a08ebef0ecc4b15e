//! One accessor for the C array family that every geometry shares
//! (`o3d_<noun>_{has_array,array_shape,set_array,get_array,array_view,array_mutable_view}` and the
//! `*_index_array` set): a [`Family`] holds one element type's functions for one handle type, and
//! its methods read, write, view and copy any array as rows of a Rust type `R` (`T`, `[T; N]` or
//! `[[T; N]; M]`) after checking that `R` is exactly one row of the array (`array_shape`).
use std::mem::size_of;
use std::ptr;
use std::slice;

use o3d_sys as sys;

use crate::error::{check, Error, ErrorCode, Result};
use crate::util::copy_out;

type Status = sys::o3d_status;

/// The array functions of handle `H` for element type `T` (f64 values, i32 indices, u8 bytes).
pub(crate) struct Family<H, T> {
    pub has: unsafe extern "C" fn(*mut i32, *const H, i32) -> Status,
    pub shape: unsafe extern "C" fn(*mut usize, *mut usize, *const H, i32) -> Status,
    pub set: unsafe extern "C" fn(*mut H, i32, *const T, usize) -> Status,
    pub get: unsafe extern "C" fn(*mut T, usize, *mut usize, *const H, i32) -> Status,
    pub view: unsafe extern "C" fn(*mut *const T, *mut usize, *const H, i32) -> Status,
    pub view_mut: unsafe extern "C" fn(*mut *mut T, *mut usize, *mut H, i32) -> Status,
    /// `set_array_f32` (float64 families but the image's).
    pub set_f32: Option<unsafe extern "C" fn(*mut H, i32, *const f32, usize) -> Status>,
}

/// A Rust wrapper around a handle with arrays.
pub(crate) trait Arrays {
    type Raw;
    fn handle(&self) -> *const Self::Raw;
    fn handle_mut(&mut self) -> *mut Self::Raw;
}

/// True when array `which` of the handle `h` counts (Open3D's `has_*`).
pub(crate) fn has<H>(
    f: unsafe extern "C" fn(*mut i32, *const H, i32) -> Status,
    h: *const H,
    which: i32,
) -> Result<bool> {
    let mut v = 0;
    // SAFETY: valid handle (the caller's borrow) and out-pointer.
    check(unsafe { f(&mut v, h, which) })?;
    Ok(v != 0)
}

/// Values per row of array `which`.
pub(crate) fn cols<H>(
    f: unsafe extern "C" fn(*mut usize, *mut usize, *const H, i32) -> Status,
    h: *const H,
    which: i32,
) -> Result<usize> {
    let (mut rows, mut cols) = (0, 0);
    // SAFETY: valid handle and out-pointers.
    check(unsafe { f(&mut rows, &mut cols, h, which) })?;
    Ok(cols)
}

impl<H, T: Copy + Default> Family<H, T> {
    /// Refuse a row type `R` that is not exactly one row of array `which`.
    fn check_row<R>(&self, h: *const H, which: i32) -> Result<()> {
        let cols = cols(self.shape, h, which)?;
        if size_of::<R>() == cols * size_of::<T>() {
            return Ok(());
        }
        let asked = size_of::<R>() / size_of::<T>();
        Err(Error::new(ErrorCode::InvalidArgument, format!("array {which} has {cols} values per row, not {asked}")))
    }

    /// True when array `which` counts.
    pub fn has<A: Arrays<Raw = H>>(&self, a: &A, which: i32) -> Result<bool> {
        has(self.has, a.handle(), which)
    }

    /// Replace array `which` with `rows` (copied once).
    pub fn set<A: Arrays<Raw = H>, R: Copy>(&self, a: &mut A, which: i32, rows: &[R]) -> Result<()> {
        self.check_row::<R>(a.handle(), which)?;
        // SAFETY: rows.len() rows of exactly one array row each, contiguous; copied by the library.
        check(unsafe { (self.set)(a.handle_mut(), which, rows.as_ptr().cast(), rows.len()) })
    }

    /// Replace float64 array `which` with float32 `rows` (`R` = `[f32; N]`), converted in the one copy.
    pub fn set_f32<A: Arrays<Raw = H>, R: Copy>(&self, a: &mut A, which: i32, rows: &[R]) -> Result<()> {
        let set = self.set_f32.ok_or_else(|| Error::new(ErrorCode::Unsupported, "no float32 input here"))?;
        if size_of::<R>() != cols(self.shape, a.handle(), which)? * size_of::<f32>() {
            return Err(Error::new(ErrorCode::InvalidArgument, format!("wrong row length for array {which}")));
        }
        // SAFETY: rows.len() rows of exactly one array row of floats each; copied by the library.
        check(unsafe { set(a.handle_mut(), which, rows.as_ptr().cast(), rows.len()) })
    }

    /// Replace array `which` with `values`, whole rows of the array's current width (feature data).
    pub fn set_flat<A: Arrays<Raw = H>>(&self, a: &mut A, which: i32, values: &[T]) -> Result<()> {
        let cols = cols(self.shape, a.handle(), which)?;
        let rows = crate::feature::rows_of(values.len(), cols)?;
        // SAFETY: rows * cols contiguous values; copied by the library.
        check(unsafe { (self.set)(a.handle_mut(), which, values.as_ptr(), rows) })
    }

    /// Zero-copy view of array `which` (empty when absent), borrowed from `a`.
    pub fn view<'a, A: Arrays<Raw = H>, R>(&self, a: &'a A, which: i32) -> Result<&'a [R]> {
        self.check_row::<R>(a.handle(), which)?;
        let (mut data, mut n) = (ptr::null(), 0);
        // SAFETY: valid handle and out-pointers.
        check(unsafe { (self.view)(&mut data, &mut n, a.handle(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&[]);
        }
        // SAFETY: n rows of one `R` each (checked above; `R`'s alignment is `T`'s), valid until the
        // next mutation of `a`, which needs `&mut` and so ends this borrow first.
        Ok(unsafe { slice::from_raw_parts(data.cast::<R>(), n) })
    }

    /// Writable zero-copy view of array `which`, exclusive for the borrow of `a`.
    pub fn view_mut<'a, A: Arrays<Raw = H>, R>(&self, a: &'a mut A, which: i32) -> Result<&'a mut [R]> {
        self.check_row::<R>(a.handle(), which)?;
        let (mut data, mut n) = (ptr::null_mut(), 0);
        // SAFETY: valid handle, exclusively borrowed, and out-pointers.
        check(unsafe { (self.view_mut)(&mut data, &mut n, a.handle_mut(), which) })?;
        if data.is_null() || n == 0 {
            return Ok(&mut []);
        }
        // SAFETY: as `view`, and unique because `a` is borrowed mutably for the slice's life.
        Ok(unsafe { slice::from_raw_parts_mut(data.cast::<R>(), n) })
    }

    /// Copy of array `which` (`get_array`).
    pub fn to_vec<A: Arrays<Raw = H>, R: Copy + Default>(&self, a: &A, which: i32) -> Result<Vec<R>> {
        self.check_row::<R>(a.handle(), which)?;
        // SAFETY: `out` has room for `cap` rows of one `R` each, or is NULL for the count query.
        copy_out::<R>(|out, cap, n| unsafe { (self.get)(out.cast(), cap, n, a.handle(), which) })
    }
}

/// `impl Arrays` for a wrapper made by `util::handle!`.
macro_rules! impl_arrays {
    ($name:ident, $raw:ty) => {
        impl crate::array::Arrays for $name {
            type Raw = $raw;
            fn handle(&self) -> *const $raw {
                self.as_raw()
            }
            fn handle_mut(&mut self) -> *mut $raw {
                self.raw_mut()
            }
        }
    };
}
pub(crate) use impl_arrays;
