//! `RgbdImage` (o3d.geometry.RGBDImage) and the back-projection of depth / RGB-D images to point
//! clouds (PointCloud.create_from_depth_image / create_from_rgbd_image).
use std::fmt;
use std::ptr;

use o3d_sys as sys;

use crate::camera::PinholeIntrinsic;
use crate::error::Result;
use crate::image::Image;
use crate::pointcloud::{new_cloud, PointCloud};
use crate::util::{c_enum, handle, mat4_ptr, options};

include!("generated/rgbd.rs");

handle! {
    /// A color (or intensity) image paired with a float depth image in metres.
    RgbdImage(sys::o3d_rgbd_image_t, "RGB-D image"), new_rgbd, sys::o3d_rgbd_image_destroy
}

impl RgbdImage {
    /// Pair `color` (8-bit, 1 or 3 channels) with `depth` (u16 or f32) of the same size.
    pub fn from_color_and_depth(color: &Image, depth: &Image, options: &RgbdOptions) -> Result<RgbdImage> {
        let opts = options.to_raw()?;
        // SAFETY: valid handles and options.
        new_rgbd(|out| unsafe {
            sys::o3d_rgbd_image_create_from_color_and_depth(out, color.as_raw(), depth.as_raw(), &opts)
        })
    }
}

impl fmt::Debug for RgbdImage {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RgbdImage").finish_non_exhaustive()
    }
}


fn extrinsic_ptr(extrinsic: Option<&[[f64; 4]; 4]>) -> *const f64 {
    extrinsic.map_or(ptr::null(), mat4_ptr)
}

impl PointCloud {
    /// Back-project a depth image (u16 raw or f32 metres) through `intrinsic`, then to world
    /// coordinates with the inverse of `extrinsic` (world-to-camera; `None`: identity).
    pub fn create_from_depth_image(
        depth: &Image,
        intrinsic: &PinholeIntrinsic,
        extrinsic: Option<&[[f64; 4]; 4]>,
        options: &DepthToCloudOptions,
    ) -> Result<PointCloud> {
        let intr = intrinsic.to_raw();
        let opts = options.to_raw()?;
        // SAFETY: valid handle, struct, NULL or 16 doubles, options.
        new_cloud(|out| unsafe {
            sys::o3d_pointcloud_create_from_depth_image(out, depth.as_raw(), &intr, extrinsic_ptr(extrinsic), &opts)
        })
    }

    /// As [`Self::create_from_depth_image`] for an RGB-D image, with per-point colors.
    pub fn create_from_rgbd_image(
        rgbd: &RgbdImage,
        intrinsic: &PinholeIntrinsic,
        extrinsic: Option<&[[f64; 4]; 4]>,
        project_valid_depth_only: bool,
    ) -> Result<PointCloud> {
        let intr = intrinsic.to_raw();
        // SAFETY: valid handle, struct, NULL or 16 doubles.
        new_cloud(|out| unsafe {
            sys::o3d_pointcloud_create_from_rgbd_image(
                out,
                rgbd.as_raw(),
                &intr,
                extrinsic_ptr(extrinsic),
                project_valid_depth_only as i32,
            )
        })
    }
}
