//! Raw FFI declarations for the o3d C API (headers `o3d/*.h`, library `libo3d.so.0`).
//!
//! Every `o3d_*` function and type and every `O3D_*` constant comes from the headers, read by
//! bindgen in `build.rs` at build time (libclang; found by pkg-config or `O3D_INCLUDE_DIR`). Macro
//! constants are `i32` like the C `int32_t` fields they fill, `size_t` is `usize`, structs keep the
//! C names (`o3d_icp_options_t`). The safe wrapper is the `o3d` crate.
//!
//! All functions are `unsafe`: the caller upholds the header's ownership, lifetime and threading
//! rules.
#![allow(non_camel_case_types, non_upper_case_globals, non_snake_case)]
// PartialEq on structs holding a callback compares its address, which is all a C caller can mean.
#![allow(unknown_lints, unpredictable_function_pointer_comparisons)]
#![no_std]

include!(concat!(env!("OUT_DIR"), "/o3d_bindings.rs"));
