//! Finds an installed libo3d, writes the FFI declarations from its headers with bindgen (libclang)
//! and tells Cargo how to link. `O3D_LIB_DIR` (folder of `libo3d.so`) and `O3D_INCLUDE_DIR` (folder of
//! `o3d/*.h`) win when set; otherwise pkg-config's `o3d.pc` (`PKG_CONFIG_PATH`) gives them. They pass on
//! to dependents as `DEP_O3D_LIB_DIR` / `DEP_O3D_INCLUDE_DIR` (`links = "o3d"`), whose build scripts add
//! the same rpath (`rustc-link-arg` does not propagate); this crate's tests get `O3D_HEADER_DIR`.
use std::env;
use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-env-changed=O3D_LIB_DIR");
    println!("cargo:rerun-if-env-changed=O3D_INCLUDE_DIR");
    // The C API version this crate declares, as build metadata of its own ("0.1.0+0.1.0").
    let version = env!("CARGO_PKG_VERSION").split('+').nth(1).unwrap_or("0");
    let (lib_dir, include_dir) = match (env::var_os("O3D_LIB_DIR"), env::var_os("O3D_INCLUDE_DIR")) {
        (Some(lib), Some(include)) => (PathBuf::from(lib), PathBuf::from(include)),
        (lib, include) => {
            if let Err(e) = pkg_config::Config::new().atleast_version(version).cargo_metadata(false).probe("o3d") {
                panic!(
                    "cannot find libo3d >= {version}: point PKG_CONFIG_PATH at the folder holding its o3d.pc \
                     (<prefix>/lib/pkgconfig), or set both O3D_LIB_DIR and O3D_INCLUDE_DIR.\n{e}"
                );
            }
            let pc = |name| PathBuf::from(pkg_config::get_variable("o3d", name).expect("a variable of o3d.pc"));
            (lib.map_or_else(|| pc("libdir"), PathBuf::from), include.map_or_else(|| pc("includedir"), PathBuf::from))
        }
    };
    let (lib_dir, include_dir) =
        (lib_dir.canonicalize().unwrap_or(lib_dir), include_dir.canonicalize().unwrap_or(include_dir));

    // Every header in the include folder, whatever its name, re-runs this script when it changes.
    let header_dir = include_dir.join("o3d");
    let entries = std::fs::read_dir(&header_dir)
        .unwrap_or_else(|e| panic!("cannot list {} (o3d headers; see O3D_INCLUDE_DIR): {e}", header_dir.display()));
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
    println!("cargo:rustc-link-search=native={}", lib_dir.display());
    println!("cargo:rustc-link-lib=dylib=o3d");
    // This crate's own tests find libo3d.so.0 without LD_LIBRARY_PATH, and read the headers.
    println!("cargo:rustc-link-arg=-Wl,-rpath,{}", lib_dir.display());
    println!("cargo:rustc-env=O3D_HEADER_DIR={}", include_dir.display());
    println!("cargo:lib_dir={}", lib_dir.display());
    println!("cargo:include_dir={}", include_dir.display());
}
