//! `Error`: a status code plus the library's thread-local message, copied out right after the
//! failing call (git2-rs `Error::last_error`).
use std::ffi::CStr;
use std::fmt;

use o3d_sys as sys;

/// What went wrong, from the C API's `o3d_status` codes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorCode {
    /// NULL handle, bad size, NaN parameter, contract broken (`O3D_ERROR_INVALID_ARGUMENT`).
    InvalidArgument,
    /// `O3D_ERROR_OUT_OF_MEMORY`.
    OutOfMemory,
    /// A file could not be opened, read or written (`O3D_ERROR_IO`).
    Io,
    /// Malformed, truncated or inconsistent data (`O3D_ERROR_PARSE`).
    Parse,
    /// Unknown format or feature not available (`O3D_ERROR_UNSUPPORTED`).
    Unsupported,
    /// Caller buffer too small (`O3D_ERROR_BUFFER_TOO_SMALL`).
    BufferTooSmall,
    /// `O3D_ERROR_NOT_CONVERGED`.
    NotConverged,
    /// A progress callback asked to stop (`O3D_ERROR_CANCELLED`).
    Cancelled,
    /// `O3D_ERROR_INTERNAL`.
    Internal,
    /// A status this crate does not know (a newer library).
    Other(i32),
}

impl ErrorCode {
    /// The code for a non-OK `o3d_status`.
    pub fn from_raw(status: sys::o3d_status) -> ErrorCode {
        match status {
            sys::O3D_ERROR_INVALID_ARGUMENT => ErrorCode::InvalidArgument,
            sys::O3D_ERROR_OUT_OF_MEMORY => ErrorCode::OutOfMemory,
            sys::O3D_ERROR_IO => ErrorCode::Io,
            sys::O3D_ERROR_PARSE => ErrorCode::Parse,
            sys::O3D_ERROR_UNSUPPORTED => ErrorCode::Unsupported,
            sys::O3D_ERROR_BUFFER_TOO_SMALL => ErrorCode::BufferTooSmall,
            sys::O3D_ERROR_NOT_CONVERGED => ErrorCode::NotConverged,
            sys::O3D_ERROR_CANCELLED => ErrorCode::Cancelled,
            sys::O3D_ERROR_INTERNAL => ErrorCode::Internal,
            other => ErrorCode::Other(other),
        }
    }

    /// The `o3d_status` value.
    pub fn raw(self) -> sys::o3d_status {
        match self {
            ErrorCode::InvalidArgument => sys::O3D_ERROR_INVALID_ARGUMENT,
            ErrorCode::OutOfMemory => sys::O3D_ERROR_OUT_OF_MEMORY,
            ErrorCode::Io => sys::O3D_ERROR_IO,
            ErrorCode::Parse => sys::O3D_ERROR_PARSE,
            ErrorCode::Unsupported => sys::O3D_ERROR_UNSUPPORTED,
            ErrorCode::BufferTooSmall => sys::O3D_ERROR_BUFFER_TOO_SMALL,
            ErrorCode::NotConverged => sys::O3D_ERROR_NOT_CONVERGED,
            ErrorCode::Cancelled => sys::O3D_ERROR_CANCELLED,
            ErrorCode::Internal => sys::O3D_ERROR_INTERNAL,
            ErrorCode::Other(raw) => raw,
        }
    }

    /// The library's static name of the code, e.g. `"O3D_ERROR_IO"` (`o3d_status_string`).
    pub fn name(self) -> String {
        // SAFETY: o3d_status_string never returns NULL and points to static storage.
        unsafe { CStr::from_ptr(sys::o3d_status_string(self.raw())) }.to_string_lossy().into_owned()
    }
}

/// An error from the o3d library (or from this crate's argument checks).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    /// What kind of failure.
    pub code: ErrorCode,
    /// The library's message (never empty).
    pub message: String,
}

/// `Result<T, o3d::Error>`.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// An error made on the Rust side (e.g. a non-UTF-8 path).
    pub fn new(code: ErrorCode, message: impl Into<String>) -> Error {
        Error { code, message: message.into() }
    }

    /// The error for `status` (non-OK), with this thread's last message, which is then cleared.
    pub(crate) fn from_status(status: sys::o3d_status) -> Error {
        let code = ErrorCode::from_raw(status);
        // SAFETY: never NULL; copied at once, before any other o3d call on this thread.
        let message = unsafe { CStr::from_ptr(sys::o3d_last_error_message()) }.to_string_lossy().into_owned();
        unsafe { sys::o3d_clear_error() };
        let message = if message.is_empty() { format!("{} (no message)", code.name()) } else { message };
        Error { code, message }
    }

    /// The last failure recorded by the library on this thread, if any (`o3d_last_error_code`).
    /// Calls made through this crate clear it after reading it, so this is mostly useful after
    /// raw `o3d-sys` calls.
    pub fn last_on_this_thread() -> Option<Error> {
        // SAFETY: plain thread-local reads.
        let status = unsafe { sys::o3d_last_error_code() };
        (status != sys::O3D_OK).then(|| Error::from_status(status))
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}: {}", self.code, self.message)
    }
}

impl std::error::Error for Error {}

/// Turn a status into a `Result`, re-raising first any panic a callback caught during the call.
pub(crate) fn check(status: sys::o3d_status) -> Result<()> {
    crate::panic::resume_if_panicked();
    if status == sys::O3D_OK {
        Ok(())
    } else {
        Err(Error::from_status(status))
    }
}
