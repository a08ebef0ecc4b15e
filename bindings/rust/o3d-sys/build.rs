//! Writes the FFI declarations from the C headers with bindgen (libclang) and tells Cargo how to link.
//!
//! * `O3D_LIB_DIR`: folder holding `libo3d.so` (default `<repo>/build/capi`, i.e.
//!   `../../../build/capi` relative to this crate).
//! * `O3D_INCLUDE_DIR`: folder holding `o3d/*.h` (default `<repo>/capi/include`).
//!
//! The library folder is also passed on to dependents as `DEP_O3D_LIB_DIR` (via `links = "o3d"`),
//! so that their build scripts can add the same rpath: `rustc-link-arg` does not propagate.
use std::env;
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let repo = manifest.join("../../..");
    let dir_from = |var: &str, default: &str| {
        println!("cargo:rerun-if-env-changed={var}");
        let dir = env::var_os(var).map(PathBuf::from).unwrap_or_else(|| repo.join(default));
        dir.canonicalize().unwrap_or(dir)
    };
    let lib_dir = dir_from("O3D_LIB_DIR", "build/capi");
    let include_dir = dir_from("O3D_INCLUDE_DIR", "capi/include");
    println!("cargo:rerun-if-changed=build.rs");

    // Every header in the include folder, whatever its name, re-runs this script when it changes.
    let header_dir = include_dir.join("o3d");
    let entries = std::fs::read_dir(&header_dir)
        .unwrap_or_else(|e| panic!("cannot list {} (set O3D_INCLUDE_DIR): {e}", header_dir.display()));
    for entry in entries {
        let path = entry.expect("header folder entry").path();
        if path.extension().is_some_and(|ext| ext == "h") {
            println!("cargo:rerun-if-changed={}", path.display());
        }
    }

    let bindings = bindgen::Builder::default()
        .header(header_dir.join("o3d.h").display().to_string())
        .clang_arg(format!("-I{}", include_dir.display()))
        .allowlist_function("o3d_.*")
        .allowlist_type("o3d_.*")
        .allowlist_var("O3D_.*")
        .default_macro_constant_type(bindgen::MacroTypeVariation::Signed)
        .size_t_is_usize(true)
        .use_core()
        .layout_tests(false)
        .derive_default(true)
        .derive_partialeq(true)
        .generate_comments(true)
        .generate()
        .expect("bindgen could not read the o3d headers");
    let out = PathBuf::from(env::var("OUT_DIR").expect("OUT_DIR")).join("o3d_bindings.rs");
    bindings.write_to_file(&out).unwrap_or_else(|e| panic!("cannot write {}: {e}", out.display()));

    // Relink when the library is rebuilt (a stale libo3d gives "undefined symbol" at link time).
    println!("cargo:rerun-if-changed={}", lib_dir.join("libo3d.so").display());
    if !lib_dir.join("libo3d.so").exists() {
        println!(
            "cargo:warning=libo3d.so not found in {} (set O3D_LIB_DIR to the folder holding it)",
            lib_dir.display()
        );
    }
    println!("cargo:rustc-link-search=native={}", lib_dir.display());
    println!("cargo:rustc-link-lib=dylib=o3d");
    // This crate's own tests find libo3d.so.0 without LD_LIBRARY_PATH.
    println!("cargo:rustc-link-arg=-Wl,-rpath,{}", lib_dir.display());
    // Metadata for dependents: DEP_O3D_LIB_DIR and DEP_O3D_INCLUDE_DIR.
    println!("cargo:lib_dir={}", lib_dir.display());
    println!("cargo:include_dir={}", include_dir.display());
}
