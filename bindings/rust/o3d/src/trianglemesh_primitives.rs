//! `TriangleMesh::create_mobius`, the primitive whose options are a struct (the others, one C call each, are
//! generated: generated/trianglemesh_ops.rs).
use o3d_sys as sys;

use crate::error::Result;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::init_struct;

impl TriangleMesh {
    /// A twisted band about the z axis, a Moebius strip for odd `twists` (Open3D's `create_mobius`):
    /// `edit` changes the library's defaults (`o3d_mobius_options_init`: 70 x 15 vertices, one twist).
    pub fn create_mobius(edit: impl FnOnce(&mut sys::o3d_mobius_options_t)) -> Result<TriangleMesh> {
        // SAFETY: plain numbers; o3d_mobius_options_init is its init.
        let mut opts = unsafe { init_struct(|p, n| sys::o3d_mobius_options_init(p, n)) }?;
        edit(&mut opts);
        // SAFETY: a valid options struct (its struct_size checked by the library).
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_create_mobius(out, &opts) })
    }
}
