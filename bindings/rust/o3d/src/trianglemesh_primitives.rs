//! `TriangleMesh::create_*`: Open3D's primitive meshes (its defaults are in each doc comment).
use o3d_sys as sys;

use crate::error::Result;
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::{init_struct, to_i32};

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

    /// UV sphere about the origin (Open3D: radius 1, resolution 20).
    pub fn create_sphere(radius: f64, resolution: usize) -> Result<TriangleMesh> {
        let r = to_i32(resolution, "resolution")?;
        // SAFETY: out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_create_sphere(out, radius, r) })
    }

    /// Cylinder along z centred at the origin (Open3D: 1, 2, 20, 4).
    pub fn create_cylinder(radius: f64, height: f64, resolution: usize, split: usize) -> Result<TriangleMesh> {
        let (r, s) = (to_i32(resolution, "resolution")?, to_i32(split, "split")?);
        // SAFETY: out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_create_cylinder(out, radius, height, r, s) })
    }

    /// Cone along z with its base at z = 0 (Open3D: 1, 2, 20, 1).
    pub fn create_cone(radius: f64, height: f64, resolution: usize, split: usize) -> Result<TriangleMesh> {
        let (r, s) = (to_i32(resolution, "resolution")?, to_i32(split, "split")?);
        // SAFETY: out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_create_cone(out, radius, height, r, s) })
    }

    /// Torus about z (Open3D: 1, 0.5, 30, 20).
    pub fn create_torus(
        torus_radius: f64,
        tube_radius: f64,
        radial_resolution: usize,
        tubular_resolution: usize,
    ) -> Result<TriangleMesh> {
        let radial = to_i32(radial_resolution, "radial_resolution")?;
        let tubular = to_i32(tubular_resolution, "tubular_resolution")?;
        // SAFETY: out-pointer.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_create_torus(out, torus_radius, tube_radius, radial, tubular) })
    }

    /// Arrow along z: a cylinder then a cone (Open3D: 1, 1.5, 5, 4, 20, 4, 1).
    #[allow(clippy::too_many_arguments)]
    pub fn create_arrow(
        cylinder_radius: f64,
        cone_radius: f64,
        cylinder_height: f64,
        cone_height: f64,
        resolution: usize,
        cylinder_split: usize,
        cone_split: usize,
    ) -> Result<TriangleMesh> {
        let r = to_i32(resolution, "resolution")?;
        let cs = to_i32(cylinder_split, "cylinder_split")?;
        let ks = to_i32(cone_split, "cone_split")?;
        // SAFETY: out-pointer.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_create_arrow(
                out,
                cylinder_radius,
                cone_radius,
                cylinder_height,
                cone_height,
                r,
                cs,
                ks,
            )
        })
    }
}
