//! Adds an rpath to libo3d's folder (reported by o3d-sys as DEP_O3D_LIB_DIR) so that this crate's
//! tests and examples find libo3d.so.0 without LD_LIBRARY_PATH. Linking itself comes from o3d-sys.
use std::env;

fn main() {
    println!("cargo:rerun-if-env-changed=DEP_O3D_LIB_DIR");
    println!("cargo:rerun-if-env-changed=DEP_O3D_INCLUDE_DIR");
    if let Ok(dir) = env::var("DEP_O3D_LIB_DIR") {
        println!("cargo:rustc-link-arg=-Wl,-rpath,{dir}");
    }
    if let Ok(dir) = env::var("DEP_O3D_INCLUDE_DIR") {
        println!("cargo:rustc-env=O3D_HEADER_DIR={dir}");
    }
}
