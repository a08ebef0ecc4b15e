//! `Image` (o3d.geometry.Image): 1, 3 or 4 interleaved channels of `u8`, `u16` or `f32`, rows top
//! to bottom.
use std::fmt;
use std::slice;

use o3d_sys as sys;

use crate::array::{impl_arrays, Family};
use crate::error::{check, Error, ErrorCode, Result};
use crate::util::{c_enum, handle};

/// The pixel type of an image (`bytes_per_channel` 1, 2 or 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PixelType {
    /// `u8`, one byte per channel.
    U8,
    /// `u16` (native byte order), e.g. raw depth in millimetres.
    U16,
    /// `f32`, e.g. depth in metres or intensity in `[0, 1]`.
    F32,
}

impl PixelType {
    /// Bytes per channel (1, 2 or 4).
    pub fn bytes(self) -> i32 {
        match self {
            PixelType::U8 => 1,
            PixelType::U16 => 2,
            PixelType::F32 => 4,
        }
    }

    fn from_bytes(bytes: i32) -> Result<PixelType> {
        match bytes {
            1 => Ok(PixelType::U8),
            2 => Ok(PixelType::U16),
            4 => Ok(PixelType::F32),
            other => Err(Error::new(ErrorCode::Internal, format!("unknown bytes_per_channel {other}"))),
        }
    }
}

include!("generated/image.rs");

handle! {
    /// A 2D image. Owns an `o3d_image_t`; `Send` and `Sync` under the same rule as [`crate::PointCloud`].
    Image(sys::o3d_image_t, "image"), new_image, sys::o3d_image_destroy, sys::o3d_image_clone
}
impl_arrays!(Image, sys::o3d_image_t);

/// The pixel bytes (`O3D_IMAGE_DATA`, one byte a row).
const BYTES: Family<sys::o3d_image_t, u8> = Family {
    has: sys::o3d_image_has_array,
    shape: sys::o3d_image_array_shape,
    set: sys::o3d_image_set_array,
    get: sys::o3d_image_get_array,
    view: sys::o3d_image_array_view,
    view_mut: sys::o3d_image_array_mutable_view,
    set_f32: None,
};

impl Image {
    /// A zero-filled `width` x `height` image of `channels` (1, 3 or 4) channels of `pixel`.
    pub fn new(width: i32, height: i32, channels: i32, pixel: PixelType) -> Result<Image> {
        // SAFETY: plain values and an out-pointer.
        new_image(|out| unsafe { sys::o3d_image_create(out, width, height, channels, pixel.bytes()) })
    }

    /// An image holding a copy of `data` (exactly width * height * channels * bytes per channel bytes).
    pub fn from_bytes(width: i32, height: i32, channels: i32, pixel: PixelType, data: &[u8]) -> Result<Image> {
        // SAFETY: data.len() readable bytes.
        new_image(|out| unsafe {
            sys::o3d_image_create_from_data(out, width, height, channels, pixel.bytes(), data.as_ptr(), data.len())
        })
    }

    /// A 1-channel `u16` image (e.g. raw depth) from `width * height` values, row by row.
    pub fn from_u16(width: i32, height: i32, values: &[u16]) -> Result<Image> {
        // SAFETY: a u16 slice viewed as its bytes (native order, as the C API wants).
        let bytes = unsafe { slice::from_raw_parts(values.as_ptr().cast::<u8>(), std::mem::size_of_val(values)) };
        Image::from_bytes(width, height, 1, PixelType::U16, bytes)
    }

    /// A 1-channel `f32` image (e.g. depth in metres) from `width * height` values, row by row.
    pub fn from_f32(width: i32, height: i32, values: &[f32]) -> Result<Image> {
        // SAFETY: an f32 slice viewed as its bytes.
        let bytes = unsafe { slice::from_raw_parts(values.as_ptr().cast::<u8>(), std::mem::size_of_val(values)) };
        Image::from_bytes(width, height, 1, PixelType::F32, bytes)
    }

    /// The pixel type.
    pub fn pixel_type(&self) -> Result<PixelType> {
        PixelType::from_bytes(self.bytes_per_channel()?)
    }

    /// Zero-copy view of the pixel bytes, borrowed from the image.
    pub fn data(&self) -> Result<&[u8]> {
        BYTES.view(self, sys::O3D_IMAGE_DATA)
    }

    /// Writable zero-copy view of the pixel bytes.
    pub fn data_mut(&mut self) -> Result<&mut [u8]> {
        BYTES.view_mut(self, sys::O3D_IMAGE_DATA)
    }

    /// Copy of the pixel bytes (`o3d_image_get_array`).
    pub fn to_vec(&self) -> Result<Vec<u8>> {
        BYTES.to_vec(self, sys::O3D_IMAGE_DATA)
    }

    /// The values of a 1-channel `f32` image (copied; alignment of the bytes is not guaranteed).
    pub fn to_f32_vec(&self) -> Result<Vec<f32>> {
        if self.pixel_type()? != PixelType::F32 {
            return Err(Error::new(ErrorCode::InvalidArgument, "to_f32_vec needs a float32 image"));
        }
        Ok(self.data()?.chunks_exact(4).map(|c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]])).collect())
    }

    /// The values of a `u16` image (copied).
    pub fn to_u16_vec(&self) -> Result<Vec<u16>> {
        if self.pixel_type()? != PixelType::U16 {
            return Err(Error::new(ErrorCode::InvalidArgument, "to_u16_vec needs a uint16 image"));
        }
        Ok(self.data()?.chunks_exact(2).map(|c| u16::from_ne_bytes([c[0], c[1]])).collect())
    }

    /// Open3D's `create_pyramid`: level 0 is a copy, each next level the previous one (Gaussian3
    /// filtered when asked) downsampled by 2. 1-channel `f32` input.
    pub fn create_pyramid(&self, num_of_levels: usize, with_gaussian_filter: bool) -> Result<Vec<Image>> {
        if self.num_channels()? != 1 || self.bytes_per_channel()? != 4 {
            return Err(Error::new(ErrorCode::InvalidArgument, "create_pyramid needs a 1-channel float32 image"));
        }
        let mut levels: Vec<Image> = Vec::with_capacity(num_of_levels);
        for i in 0..num_of_levels {
            let next = if i == 0 {
                self.try_clone()?
            } else if with_gaussian_filter {
                levels[i - 1].filter(ImageFilter::Gaussian3)?.downsample()?
            } else {
                levels[i - 1].downsample()?
            };
            levels.push(next);
        }
        Ok(levels)
    }
}

impl fmt::Debug for Image {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Image")
            .field("width", &self.width().unwrap_or(0))
            .field("height", &self.height().unwrap_or(0))
            .field("channels", &self.num_channels().unwrap_or(0))
            .field("bytes_per_channel", &self.bytes_per_channel().unwrap_or(0))
            .finish()
    }
}
