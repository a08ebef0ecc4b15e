//! No unwinding across FFI (git2-rs `panic.rs`): every Rust callback the library calls runs inside
//! `catch_unwind`; a panic is parked in a thread-local, the callback reports failure to C, and the
//! panic resumes once control is back in Rust (in `error::check`).
use std::any::Any;
use std::cell::RefCell;
use std::panic::{self, AssertUnwindSafe};

thread_local! {
    static LAST_PANIC: RefCell<Option<Box<dyn Any + Send>>> = const { RefCell::new(None) };
}

/// Run `f`, returning `None` (and parking the panic) if it panicked.
pub(crate) fn wrap<T>(f: impl FnOnce() -> T) -> Option<T> {
    // A previous panic is still waiting to resume: run nothing more on this thread.
    if LAST_PANIC.with(|p| p.borrow().is_some()) {
        return None;
    }
    match panic::catch_unwind(AssertUnwindSafe(f)) {
        Ok(value) => Some(value),
        Err(payload) => {
            LAST_PANIC.with(|p| *p.borrow_mut() = Some(payload));
            None
        }
    }
}

/// Resume a panic parked by `wrap` on this thread.
pub(crate) fn resume_if_panicked() {
    if let Some(payload) = LAST_PANIC.with(|p| p.borrow_mut().take()) {
        panic::resume_unwind(payload);
    }
}
