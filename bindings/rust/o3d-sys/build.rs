//! Finds libo3d and tells Cargo how to link it.
//!
//! * `O3D_LIB_DIR`: folder holding `libo3d.so` (default `<repo>/build/capi`, i.e.
//!   `../../../build/capi` relative to this crate).
//! * `O3D_INCLUDE_DIR`: folder holding `o3d/*.h` (default `<repo>/capi/include`); only watched for
//!   changes here, and read by the drift tests.
//!
//! The library folder is also passed on to dependents as `DEP_O3D_LIB_DIR` (via `links = "o3d"`),
//! so that their build scripts can add the same rpath: `rustc-link-arg` does not propagate.
use std::env;
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let repo = manifest.join("../../..");

    println!("cargo:rerun-if-env-changed=O3D_LIB_DIR");
    println!("cargo:rerun-if-env-changed=O3D_INCLUDE_DIR");
    println!("cargo:rerun-if-changed=build.rs");

    let lib_dir = env::var_os("O3D_LIB_DIR").map(PathBuf::from).unwrap_or_else(|| repo.join("build/capi"));
    let lib_dir = lib_dir.canonicalize().unwrap_or(lib_dir);
    let include_dir = env::var_os("O3D_INCLUDE_DIR").map(PathBuf::from).unwrap_or_else(|| repo.join("capi/include"));
    let include_dir = include_dir.canonicalize().unwrap_or(include_dir);

    for header in [
        "o3d.h",
        "common.h",
        "pointcloud.h",
        "kdtree.h",
        "feature.h",
        "io.h",
        "registration.h",
        "posegraph.h",
        "image.h",
        "camera.h",
        "rgbd.h",
        "trianglemesh.h",
        "boundingbox.h",
        "hull.h",
        "lineset.h",
        "voxelgrid.h",
        "octree.h",
    ] {
        println!("cargo:rerun-if-changed={}", include_dir.join("o3d").join(header).display());
    }
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
