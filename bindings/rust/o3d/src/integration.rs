//! TSDF integration (o3d.pipelines.integration): [`TSDFVolume`], Open3D's UniformTSDFVolume and
//! ScalableTSDFVolume behind one type. The constructors (`new_uniform`, `new_scalable`), reset,
//! extraction and getters are generated; written here: `integrate` and the uniform volume's arrays.
use o3d_sys as sys;

use crate::camera::PinholeIntrinsic;
use crate::error::{check, Result};
use crate::pointcloud::PointCloud;
use crate::rgbd::RgbdImage;
use crate::trianglemesh::TriangleMesh;
use crate::util::{c_enum, copy_out, handle, mat4_ptr};
use crate::voxelgrid::VoxelGrid;

include!("generated/integration.rs");

handle! {
    /// A truncated signed distance volume: integrate RGB-D frames, extract the surface.
    ///
    /// Owns an `o3d_tsdf_volume_t`. `Send` and `Sync`: `&self` methods only make `const` C calls and
    /// every change takes `&mut self`.
    TSDFVolume(sys::o3d_tsdf_volume_t, "TSDF volume"), new_volume, sys::o3d_tsdf_volume_destroy
}

impl TSDFVolume {
    /// Fuse a frame seen by `intrinsic` from `extrinsic` (row-major, world to camera). Depth is float
    /// metres; colour 8-bit RGB for RGB8, float intensity for Gray32.
    pub fn integrate(&mut self, image: &RgbdImage, intrinsic: &PinholeIntrinsic, extrinsic: &[[f64; 4]; 4]) -> Result<()> {
        let intr = intrinsic.to_raw();
        // SAFETY: valid handles, a struct and 16 doubles that live for the call.
        check(unsafe { sys::o3d_tsdf_volume_integrate(self.raw_mut(), image.as_raw(), &intr, mat4_ptr(extrinsic)) })
    }

    /// A uniform volume's (tsdf, weight) per voxel, voxel (x, y, z) at (x * resolution + y) * resolution + z.
    pub fn extract_volume_tsdf(&self) -> Result<Vec<[f32; 2]>> {
        // SAFETY: a valid handle; `out` holds `cap` rows of 2 floats.
        copy_out(|out: *mut [f32; 2], cap, n| unsafe {
            sys::o3d_tsdf_volume_extract_volume_tsdf(out.cast(), cap, n, self.as_raw())
        })
    }

    /// A uniform volume's RGB in [0, 1] per voxel, in the same order.
    pub fn extract_volume_color(&self) -> Result<Vec<[f32; 3]>> {
        // SAFETY: a valid handle; `out` holds `cap` rows of 3 floats.
        copy_out(|out: *mut [f32; 3], cap, n| unsafe {
            sys::o3d_tsdf_volume_extract_volume_color(out.cast(), cap, n, self.as_raw())
        })
    }
}
