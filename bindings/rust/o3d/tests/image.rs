//! Image: creation, views, conversions, filters, encode/decode round trips and errors.
mod common;

use common::*;
use o3d::io;
use o3d::{ConvertType, ErrorCode, Image, ImageFilter, PixelType};

/// A width x height float image with pixel (u, v) = u (a horizontal ramp).
fn ramp(width: i32, height: i32) -> Image {
    let values: Vec<f32> = (0..height).flat_map(|_| (0..width).map(|u| u as f32)).collect();
    Image::from_f32(width, height, &values).unwrap()
}

#[test]
fn new_images_are_zeroed_and_described() {
    let img = Image::new(3, 2, 3, PixelType::U8).unwrap();
    assert_eq!((img.width().unwrap(), img.height().unwrap()), (3, 2));
    assert_eq!(img.num_channels().unwrap(), 3);
    assert_eq!(img.bytes_per_channel().unwrap(), 1);
    assert_eq!(img.pixel_type().unwrap(), PixelType::U8);
    assert_eq!(img.data().unwrap(), &[0u8; 18]);
    let depth = Image::new(4, 4, 1, PixelType::U16).unwrap();
    assert_eq!(depth.to_vec().unwrap().len(), 32);
    assert_eq!(depth.to_u16_vec().unwrap(), vec![0u16; 16]);
}

#[test]
fn bad_shapes_are_errors() {
    assert_eq!(Image::new(0, 2, 1, PixelType::U8).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(Image::new(2, 2, 2, PixelType::U8).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(Image::from_bytes(2, 2, 1, PixelType::U8, &[1, 2, 3]).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(Image::from_u16(2, 2, &[1, 2, 3, 4, 5]).unwrap_err().code, ErrorCode::InvalidArgument);
    // Filters need 1-channel float input.
    let gray8 = Image::new(4, 4, 1, PixelType::U8).unwrap();
    assert_eq!(gray8.filter(ImageFilter::Gaussian3).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(gray8.to_f32_vec().unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn mutable_view_and_clone() {
    let mut img = Image::from_bytes(2, 1, 3, PixelType::U8, &[1, 2, 3, 4, 5, 6]).unwrap();
    let copy = img.clone();
    img.data_mut().unwrap()[0] = 200;
    assert_eq!(img.data().unwrap(), &[200, 2, 3, 4, 5, 6]);
    assert_eq!(copy.data().unwrap(), &[1, 2, 3, 4, 5, 6]);
}

#[test]
fn flips() {
    // 2x2 gray: [[1, 2], [3, 4]].
    let img = Image::from_bytes(2, 2, 1, PixelType::U8, &[1, 2, 3, 4]).unwrap();
    assert_eq!(img.flip_vertical().unwrap().data().unwrap(), &[3, 4, 1, 2]);
    assert_eq!(img.flip_horizontal().unwrap().data().unwrap(), &[2, 1, 4, 3]);
    // Flipping keeps all channels of a pixel together.
    let rgb = Image::from_bytes(2, 1, 3, PixelType::U8, &[1, 2, 3, 4, 5, 6]).unwrap();
    assert_eq!(rgb.flip_horizontal().unwrap().data().unwrap(), &[4, 5, 6, 1, 2, 3]);
}

#[test]
fn float_conversions() {
    let red = Image::from_bytes(1, 1, 3, PixelType::U8, &[255, 0, 0]).unwrap();
    let weighted = red.create_float_image(ConvertType::Weighted).unwrap().to_f32_vec().unwrap();
    assert!((weighted[0] - 0.299).abs() < 1e-6, "{weighted:?}");
    let equal = red.create_float_image(ConvertType::Equal).unwrap().to_f32_vec().unwrap();
    assert!((equal[0] - 1.0 / 3.0).abs() < 1e-6, "{equal:?}");
    let gray16 = Image::from_u16(2, 1, &[7, 65535]).unwrap();
    assert_eq!(gray16.create_float_image(ConvertType::default()).unwrap().to_f32_vec().unwrap(), vec![7.0, 65535.0]);

    let depth = Image::from_u16(4, 1, &[1000, 5000, 0, 2500]).unwrap();
    let metres = depth.convert_depth_to_float(1000.0, 3.0).unwrap();
    assert_eq!(metres.pixel_type().unwrap(), PixelType::F32);
    assert_eq!(metres.to_f32_vec().unwrap(), vec![1.0, 0.0, 0.0, 2.5]);
    assert_eq!(depth.convert_depth_to_float(0.0, 3.0).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn filters_on_a_ramp() {
    // f(u, v) = u. Edge pixels are replicated, so the unnormalised Sobel x kernel ([-1 0 1] times
    // [1 2 1]) gives 4 * (f(u+1) - f(u-1)) = 8 inside and 4 at the two border columns, and the
    // 3-tap Gaussian (1/4, 1/2, 1/4) keeps interior values and gives 0.25 and 3.75 at the borders
    // (Open3D 0.20 gives the same for Image.filter(Sobel3dx / Gaussian3) on this ramp).
    let img = ramp(5, 4);
    let sobel = img.filter(ImageFilter::Sobel3Dx).unwrap().to_f32_vec().unwrap();
    for row in sobel.chunks(5) {
        assert_eq!(row, &[4.0, 8.0, 8.0, 8.0, 4.0]);
    }
    let dy = img.filter(ImageFilter::Sobel3Dy).unwrap().to_f32_vec().unwrap();
    assert!(dy.iter().all(|&v| v == 0.0));
    let gauss = img.filter(ImageFilter::Gaussian3).unwrap().to_f32_vec().unwrap();
    for row in gauss.chunks(5) {
        assert_eq!(row, &[0.25, 1.0, 2.0, 3.0, 3.75]);
    }
    for filter in [ImageFilter::Gaussian5, ImageFilter::Gaussian7] {
        let constant = Image::from_f32(8, 8, &[2.5; 64]).unwrap().filter(filter).unwrap();
        assert!(constant.to_f32_vec().unwrap().iter().all(|&v| (v - 2.5).abs() < 1e-5));
    }
}

#[test]
fn downsample_takes_two_by_two_means() {
    let values: Vec<f32> = (0..16).map(|i| i as f32).collect();
    let half = Image::from_f32(4, 4, &values).unwrap().downsample().unwrap();
    assert_eq!((half.width().unwrap(), half.height().unwrap()), (2, 2));
    // Block means: (0+1+4+5)/4, (2+3+6+7)/4, ...
    assert_eq!(half.to_f32_vec().unwrap(), vec![2.5, 4.5, 10.5, 12.5]);
}

#[test]
fn lossless_round_trips_in_memory() {
    let mut rng = Rng::new(5);
    let rgb: Vec<u8> = (0..5 * 3 * 3).map(|_| (rng.next_f64() * 255.0) as u8).collect();
    let img = Image::from_bytes(5, 3, 3, PixelType::U8, &rgb).unwrap();
    for format in ["png", "ppm"] {
        let bytes = io::write_image_to_memory(&img, format, None).unwrap();
        let back = io::read_image_from_memory(&bytes, format).unwrap();
        assert_eq!((back.width().unwrap(), back.height().unwrap(), back.num_channels().unwrap()), (5, 3, 3));
        assert_eq!(back.data().unwrap(), img.data().unwrap(), "{format}");
    }
    let depth = Image::from_u16(3, 2, &[0, 1, 1000, 4095, 40000, 65535]).unwrap();
    for format in ["png", "pgm"] {
        let buffer = io::write_image_to_buffer(&depth, format, None).unwrap();
        let back = io::read_image_from_memory(buffer.as_bytes().unwrap(), format).unwrap();
        assert_eq!(back.to_u16_vec().unwrap(), depth.to_u16_vec().unwrap(), "{format}");
    }
    let rgba = Image::from_bytes(1, 2, 4, PixelType::U8, &[1, 2, 3, 4, 5, 6, 7, 8]).unwrap();
    let back = io::read_image_from_memory(&io::write_image_to_memory(&rgba, "png", None).unwrap(), "png").unwrap();
    assert_eq!(back.data().unwrap(), rgba.data().unwrap());
}

#[test]
fn jpeg_is_close_and_quality_matters() {
    // A smooth gradient survives JPEG within a few levels.
    let gray: Vec<u8> = (0..16 * 16).map(|i| ((i % 16) * 8 + (i / 16) * 4) as u8).collect();
    let img = Image::from_bytes(16, 16, 1, PixelType::U8, &gray).unwrap();
    let high = io::write_image_to_memory(&img, "jpg", Some(100)).unwrap();
    let low = io::write_image_to_memory(&img, "jpg", Some(5)).unwrap();
    assert!(low.len() < high.len());
    let back = io::read_image_from_memory(&high, "jpg").unwrap();
    let worst = back.data().unwrap().iter().zip(&gray).map(|(a, b)| (*a as i32 - *b as i32).abs()).max().unwrap();
    assert!(worst <= 4, "max error {worst}");
}

#[test]
fn image_io_errors() {
    let float = Image::new(2, 2, 1, PixelType::F32).unwrap();
    assert!(io::write_image_to_memory(&float, "png", None).is_err());
    assert!(io::read_image_from_memory(b"\x89PNG garbage", "png").is_err());
    assert_eq!(io::read_image("/nonexistent/x.png", "auto").unwrap_err().code, ErrorCode::Io);
    let dir = TempDir::new("image");
    let img = Image::from_bytes(2, 2, 1, PixelType::U8, &[0, 64, 128, 255]).unwrap();
    let path = dir.path("gray.png");
    io::write_image(&path, &img, "auto", None).unwrap();
    assert_eq!(io::read_image(&path, "auto").unwrap().data().unwrap(), img.data().unwrap());
}

#[test]
fn shared_rgbd_frame_decodes() {
    let (Some(color), Some(depth)) =
        (data_file("open3d/RGBD/color/00000.jpg"), data_file("open3d/RGBD/depth/00000.png"))
    else {
        return;
    };
    let color = io::read_image(color, "auto").unwrap();
    assert_eq!((color.width().unwrap(), color.height().unwrap(), color.num_channels().unwrap()), (640, 480, 3));
    let depth = io::read_image(depth, "auto").unwrap();
    assert_eq!(depth.pixel_type().unwrap(), PixelType::U16);
    assert_eq!(depth.num_channels().unwrap(), 1);
}

#[test]
fn create_pyramid_halves_each_level_and_keeps_a_constant() {
    let img = Image::from_f32(8, 4, &[0.5f32; 32]).unwrap();
    let levels = img.create_pyramid(3, true).unwrap();
    let sizes: Vec<(i32, i32)> = levels.iter().map(|l| (l.width().unwrap(), l.height().unwrap())).collect();
    assert_eq!(sizes, vec![(8, 4), (4, 2), (2, 1)]);
    for level in &levels {
        assert!(level.to_f32_vec().unwrap().iter().all(|&v| v == 0.5));
    }
    // Without the filter, level 1 is exactly the 2x2 means of the ramp.
    let plain = ramp(4, 2).create_pyramid(2, false).unwrap();
    assert_eq!(plain[1].to_f32_vec().unwrap(), vec![0.5, 2.5]);
    let gray8 = Image::new(4, 4, 1, PixelType::U8).unwrap();
    assert_eq!(gray8.create_pyramid(2, true).unwrap_err().code, ErrorCode::InvalidArgument);
}
