//! `RgbdImage` (o3d.geometry.RGBDImage) and the back-projection of depth / RGB-D images to point
//! clouds (PointCloud.create_from_depth_image / create_from_rgbd_image).
use std::fmt;
use std::ptr;

use o3d_sys as sys;

use crate::camera::PinholeIntrinsic;
use crate::error::Result;
use crate::image::{new_image, Image};
use crate::pointcloud::{new_cloud, PointCloud};
use crate::util::{handle, init_struct, mat4_ptr};

/// RGBDImage.create_from_color_and_depth keyword arguments (Open3D's defaults).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RgbdOptions {
    /// Raw depth units per metre (default 1000).
    pub depth_scale: f64,
    /// Depths beyond this many metres become 0 (default 3).
    pub depth_trunc: f64,
    /// Turn the color into a 1-channel float intensity (default true).
    pub convert_rgb_to_intensity: bool,
}

impl Default for RgbdOptions {
    fn default() -> Self {
        RgbdOptions { depth_scale: 1000.0, depth_trunc: 3.0, convert_rgb_to_intensity: true }
    }
}

impl RgbdOptions {
    fn to_raw(self) -> Result<sys::o3d_rgbd_options_t> {
        // SAFETY: o3d_rgbd_options_t is plain numbers and nullable pointers; o3d_rgbd_options_init is its init.
        let mut raw = unsafe { init_struct(|p, n| sys::o3d_rgbd_options_init(p, n)) }?;
        raw.depth_scale = self.depth_scale;
        raw.depth_trunc = self.depth_trunc;
        raw.convert_rgb_to_intensity = self.convert_rgb_to_intensity as i32;
        Ok(raw)
    }
}

/// The dataset layouts of [`RgbdImage::from_dataset_format`] (`O3D_RGBD_FORMAT_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RgbdFormat {
    /// Depth in mm, truncated at 4 m.
    Redwood,
    /// Depth scale 5000, truncated at 4 m.
    Tum,
    /// SUN RGB-D: depth bits rotated right by 3, in mm, truncated at 7 m.
    Sun,
    /// NYU raw PGM disparity, truncated at 7 m.
    Nyu,
}

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

    /// One of the dataset readers of the Open3D paper (create_from_{redwood,tum,sun,nyu}_format).
    pub fn from_dataset_format(
        format: RgbdFormat,
        color: &Image,
        depth: &Image,
        convert_rgb_to_intensity: bool,
    ) -> Result<RgbdImage> {
        let raw_format = match format {
            RgbdFormat::Redwood => sys::O3D_RGBD_FORMAT_REDWOOD,
            RgbdFormat::Tum => sys::O3D_RGBD_FORMAT_TUM,
            RgbdFormat::Sun => sys::O3D_RGBD_FORMAT_SUN,
            RgbdFormat::Nyu => sys::O3D_RGBD_FORMAT_NYU,
        };
        // SAFETY: valid handles.
        new_rgbd(|out| unsafe {
            sys::o3d_rgbd_image_create_from_dataset_format(
                out,
                raw_format,
                color.as_raw(),
                depth.as_raw(),
                convert_rgb_to_intensity as i32,
            )
        })
    }

    /// A copy of the color (or intensity) image.
    pub fn color(&self) -> Result<Image> {
        // SAFETY: valid handle.
        new_image(|out| unsafe { sys::o3d_rgbd_image_get_color(out, self.as_raw()) })
    }

    /// A copy of the depth image (1-channel f32, metres).
    pub fn depth(&self) -> Result<Image> {
        // SAFETY: valid handle.
        new_image(|out| unsafe { sys::o3d_rgbd_image_get_depth(out, self.as_raw()) })
    }
}

impl fmt::Debug for RgbdImage {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RgbdImage").finish_non_exhaustive()
    }
}

/// PointCloud.create_from_depth_image keyword arguments (Open3D's defaults).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DepthToCloudOptions {
    /// Raw units per metre for u16 depth (default 1000).
    pub depth_scale: f64,
    /// Farther depths are dropped, in metres (default 1000).
    pub depth_trunc: f64,
    /// Use every `stride`-th pixel in x and y (default 1).
    pub stride: i32,
    /// False: invalid pixels give NaN points (an organised cloud). Default true.
    pub project_valid_depth_only: bool,
}

impl Default for DepthToCloudOptions {
    fn default() -> Self {
        DepthToCloudOptions { depth_scale: 1000.0, depth_trunc: 1000.0, stride: 1, project_valid_depth_only: true }
    }
}

impl DepthToCloudOptions {
    fn to_raw(self) -> Result<sys::o3d_depth_to_cloud_options_t> {
        // SAFETY: o3d_depth_to_cloud_options_t is plain numbers and nullable pointers; o3d_depth_to_cloud_options_init is its init.
        let mut raw = unsafe { init_struct(|p, n| sys::o3d_depth_to_cloud_options_init(p, n)) }?;
        raw.depth_scale = self.depth_scale;
        raw.depth_trunc = self.depth_trunc;
        raw.stride = self.stride;
        raw.project_valid_depth_only = self.project_valid_depth_only as i32;
        Ok(raw)
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
