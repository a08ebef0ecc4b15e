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

/// Run a C call writing an `o3d_index_lists_t` and copy the lists out as `i32`s (the handle is freed
/// here, also when the call or the copy fails).
pub(crate) fn index_lists_i32(
    f: impl FnOnce(*mut *mut sys::o3d_index_lists_t) -> sys::o3d_status,
) -> Result<Vec<Vec<i32>>> {
    let mut raw = ptr::null_mut();
    let status = f(&mut raw);
    let owned = IndexLists(raw);
    check(status)?;
    owned.to_vecs()
}

/// Run a C call writing an `o3d_index_lists_t` of indices (never negative) and copy them out (Open3D's
/// `List[IntVector]`).
pub(crate) fn index_lists(
    f: impl FnOnce(*mut *mut sys::o3d_index_lists_t) -> sys::o3d_status,
) -> Result<Vec<Vec<usize>>> {
    index_lists_i32(f)?.into_iter().map(|list| list.into_iter().map(index).collect()).collect()
}

/// A C index (documented non-negative) as `usize`; a negative one is an `Internal` error.
pub(crate) fn index(i: i32) -> Result<usize> {
    usize::try_from(i).map_err(|_| Error::new(ErrorCode::Internal, format!("the library returned index {i}")))
}

/// An owned `o3d_index_lists_t` (NULL allowed), destroyed on drop.
pub(crate) struct IndexLists(pub(crate) *mut sys::o3d_index_lists_t);

impl IndexLists {
    /// The lists, each a `Vec` (offsets and values copied once).
    pub(crate) fn to_vecs(&self) -> Result<Vec<Vec<i32>>> {
        let (mut num_lists, mut total) = (0usize, 0usize);
        // SAFETY: the handle (or NULL, an error) and out-pointers.
        check(unsafe { sys::o3d_index_lists_num_lists(&mut num_lists, self.0) })?;
        // SAFETY: as above.
        check(unsafe { sys::o3d_index_lists_num_values(&mut total, self.0) })?;
        let mut offsets = vec![0i64; num_lists + 1];
        let mut values = vec![0i32; total];
        let mut n = 0usize;
        // SAFETY: buffers of the lengths passed.
        check(unsafe { sys::o3d_index_lists_get_offsets(offsets.as_mut_ptr(), offsets.len(), &mut n, self.0) })?;
        // SAFETY: as above.
        check(unsafe { sys::o3d_index_lists_get_values(values.as_mut_ptr(), values.len(), &mut n, self.0) })?;
        offsets
            .windows(2)
            .map(|w| {
                let (a, b) = (usize::try_from(w[0]), usize::try_from(w[1]));
                match (a, b) {
                    (Ok(a), Ok(b)) if a <= b && b <= values.len() => Ok(values[a..b].to_vec()),
                    _ => Err(Error::new(ErrorCode::Internal, "the library returned bad index-list offsets")),
                }
            })
            .collect()
    }
}

impl Drop for IndexLists {
    fn drop(&mut self) {
        // SAFETY: owned (or NULL, a no-op), destroyed once.
        unsafe { sys::o3d_index_lists_destroy(self.0) }
    }
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

/// A Rust field of an options type and its C counterpart `C` (one C field, or a tuple of them).
pub(crate) trait CField<C>: Sized {
    /// The C value; `name` names the field in an error (e.g. a count too large for `int32_t`).
    fn to_c(&self, name: &str) -> Result<C>;
    /// The Rust value; an unknown enum constant is an `Internal` error.
    fn from_c(c: C) -> Result<Self>;
}

/// `CField` impls from a table: Rust type => C type: to C (self, field name), from C (value).
macro_rules! c_fields {
    ($($(#[$doc:meta])* $rust:ty => $c:ty: |$s:ident, $name:pat_param| $to:expr, |$v:pat_param| $from:expr;)+) => {
        $($(#[$doc])*
        impl CField<$c> for $rust {
            fn to_c(&self, $name: &str) -> Result<$c> {
                let $s = *self;
                $to
            }
            fn from_c($v: $c) -> Result<$rust> {
                Ok($from)
            }
        })+
    };
}

c_fields! {
    f64 => f64: |s, _| Ok(s), |c| c;
    i32 => i32: |s, _| Ok(s), |c| c;
    /// C flags: non-zero is true.
    bool => i32: |s, _| Ok(s as i32), |c| c != 0;
    /// Counts: `int32_t` in C, checked on the way in.
    usize => i32: |s, name| to_i32(s, name), |c| c.max(0) as usize;
    /// An optional index: a negative `int32_t` is `None`.
    Option<usize> => i32: |s, name| s.map_or(Ok(-1), |n| to_i32(n, name)), |c| usize::try_from(c).ok();
    /// An optional seed: the pair (`use_seed`, `seed`).
    Option<u64> => (i32, u64): |s, _| Ok((s.is_some() as i32, s.unwrap_or(0))), |(use_seed, seed)| (use_seed != 0).then_some(seed);
}

/// A fixed-size C array (`double x[N]`) as the same Rust array.
impl<const N: usize> CField<[f64; N]> for [f64; N] {
    fn to_c(&self, _: &str) -> Result<[f64; N]> {
        Ok(*self)
    }
    fn from_c(c: [f64; N]) -> Result<Self> {
        Ok(c)
    }
}

/// A row-major R x C matrix (a 4x4 transform, four lights' RGB) as the C API's `R * C` contiguous doubles
/// (`N` must be `R * C`).
impl<const R: usize, const C: usize, const N: usize> CField<[f64; N]> for [[f64; C]; R] {
    fn to_c(&self, _: &str) -> Result<[f64; N]> {
        let mut out = [0.0; N];
        for (chunk, row) in out.chunks_exact_mut(C).zip(self) {
            chunk.copy_from_slice(row);
        }
        Ok(out)
    }
    fn from_c(c: [f64; N]) -> Result<Self> {
        let mut m = [[0.0; C]; R];
        for (row, chunk) in m.iter_mut().zip(c.chunks_exact(C)) {
            row.copy_from_slice(chunk);
        }
        Ok(m)
    }
}

/// The C field(s) named in an [`options!`] line: `field` or `(field, field, ...)`.
macro_rules! c_place {
    ($raw:ident ($($c:ident),+)) => { ($($raw.$c),+) };
    ($raw:ident $c:ident) => { $raw.$c };
}
pub(crate) use c_place;

/// An options type over a versioned C struct: the struct with its documented public fields, each
/// mapped to C field(s) through [`CField`]; `Default` and `library_defaults` are what the C
/// `*_init` function writes; crate-private `raw_default` / `to_raw` (the init's struct with the
/// fields set) / `from_raw`. Its invocations (and `c_enum!`'s) are generated from the C headers into
/// src/generated/ by tools/gen_binding_tables.py.
macro_rules! options {
    ($(#[$doc:meta])* pub struct $name:ident($raw:ty, $init:path) {
        $($(#[$fdoc:meta])* pub $field:ident: $ty:ty = $c:tt,)+
    }) => {
        $(#[$doc])*
        pub struct $name {
            $($(#[$fdoc])* pub $field: $ty,)+
        }

        impl Default for $name {
            /// The library's defaults (see `library_defaults`); panics only if the library rejects
            /// its own struct (a mismatched libo3d).
            fn default() -> Self {
                Self::library_defaults().unwrap_or_else(|e| panic!("{} failed: {e}", stringify!($init)))
            }
        }

        impl $name {
            #[doc = concat!("The library's defaults (`", stringify!($init), "`), as `Default` but an error where it fails.")]
            pub fn library_defaults() -> crate::Result<Self> {
                Self::from_raw(&Self::raw_default()?)
            }

            #[allow(dead_code)]
            pub(crate) fn raw_default() -> crate::Result<$raw> {
                // SAFETY: options structs are plain numbers and nullable pointers; $init is its init.
                unsafe { crate::util::init_struct(|p, n| $init(p, n)) }
            }

            #[allow(dead_code)]
            pub(crate) fn to_raw(self) -> crate::Result<$raw> {
                let mut raw = Self::raw_default()?;
                $(crate::util::c_place!(raw $c) = crate::util::CField::to_c(&self.$field, stringify!($field))?;)+
                Ok(raw)
            }

            pub(crate) fn from_raw(raw: &$raw) -> crate::Result<Self> {
                Ok($name { $($field: crate::util::CField::from_c(crate::util::c_place!(raw $c))?,)+ })
            }
        }
    };
}
pub(crate) use options;

/// A Rust enum over C constants: each variant's discriminant is its `O3D_*` constant; crate-private
/// `raw` / `from_raw` (an unknown constant is an `Internal` error) and the [`CField`] mapping.
macro_rules! c_enum {
    ($(#[$doc:meta])* pub enum $name:ident($what:literal) { $($(#[$vdoc:meta])* $variant:ident = $c:path,)+ }) => {
        $(#[$doc])*
        #[repr(i32)]
        pub enum $name {
            $($(#[$vdoc])* $variant = $c,)+
        }

        #[allow(dead_code)]
        impl $name {
            pub(crate) fn raw(self) -> i32 {
                self as i32
            }

            pub(crate) fn from_raw(raw: i32) -> crate::Result<Self> {
                $(if raw == $c {
                    return Ok($name::$variant);
                })+
                Err(crate::Error::new(crate::ErrorCode::Internal, format!("unknown {} {raw}", $what)))
            }
        }

        impl crate::util::CField<i32> for $name {
            fn to_c(&self, _: &str) -> crate::Result<i32> {
                Ok(self.raw())
            }
            fn from_c(c: i32) -> crate::Result<Self> {
                Self::from_raw(c)
            }
        }
    };
}
pub(crate) use c_enum;
