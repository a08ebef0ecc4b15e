//! TSDF volumes: a fronto-parallel plane comes back at its depth (exact projective distances), Open3D's
//! tutorial frames against Open3D 0.20's uniform volume (tools/reference/record_tsdf.py: 147927
//! vertices, 280605 triangles; its scalable volume is empty there), and the errors.
mod common;

use common::*;
use o3d::integration::{TSDFVolume, TSDFVolumeColorType};
use o3d::io;
use o3d::{ErrorCode, Image, PinholeIntrinsic, PixelType, RgbdImage, RgbdOptions};

const W: i32 = 160;
const H: i32 = 120;
const IDENTITY: [[f64; 4]; 4] = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

fn small() -> PinholeIntrinsic {
    PinholeIntrinsic::new(W, H, 100.0, 100.0, 79.5, 59.5)
}

fn plane_frame(rgb: bool) -> RgbdImage {
    let color: Vec<u8> = (0..W * H).flat_map(|_| [200u8, 100, 50]).collect();
    let color = Image::from_bytes(W, H, 3, PixelType::U8, &color).unwrap();
    let depth = Image::from_f32(W, H, &vec![1.0f32; (W * H) as usize]).unwrap();
    let options = RgbdOptions { depth_scale: 1.0, convert_rgb_to_intensity: !rgb, ..Default::default() };
    RgbdImage::from_color_and_depth(&color, &depth, &options).unwrap()
}

#[test]
fn plane_comes_back_at_its_depth() {
    let mut volume = TSDFVolume::new_uniform(1.0, 64, 0.04, TSDFVolumeColorType::Rgb8, Some([-0.5, -0.5, 0.5])).unwrap();
    volume.integrate(&plane_frame(true), &small(), &IDENTITY).unwrap();
    let mesh = volume.extract_triangle_mesh().unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 64 * 64);
    assert_eq!(mesh.num_triangles().unwrap(), 2 * 63 * 63);
    for v in mesh.vertices().unwrap() {
        assert!((v[2] - 1.0).abs() < 1e-4, "{v:?}");
    }
    let tsdf = volume.extract_volume_tsdf().unwrap();
    assert_eq!(tsdf.len(), 64 * 64 * 64);
    let voxel = tsdf[(32 * 64 + 32) * 64 + 30];
    assert!((voxel[0] as f64 - (1.0 - (0.5 + 30.5 / 64.0)) / 0.04).abs() < 1e-4, "{voxel:?}");
    assert_eq!(voxel[1], 1.0);
    assert_eq!(volume.color_type().unwrap(), TSDFVolumeColorType::Rgb8);
    assert_eq!(volume.resolution().unwrap(), 64);
    assert!(!volume.is_scalable().unwrap());
    volume.reset().unwrap();
    assert_eq!(volume.extract_triangle_mesh().unwrap().num_vertices().unwrap(), 0);
}

#[test]
fn open3d_tutorial_frames() {
    let Some(log) = data_file("open3d/RGBD/trajectory.log") else { return };
    let poses = io::read_pinhole_camera_trajectory(&log, "").unwrap();
    let mut volume = TSDFVolume::new_scalable(4.0 / 512.0, 0.04, TSDFVolumeColorType::Rgb8, 16, 4).unwrap();
    let options = RgbdOptions { depth_trunc: 4.0, convert_rgb_to_intensity: false, ..Default::default() };
    for i in 0..poses.len().unwrap() {
        let color = io::read_image(data_file(&format!("open3d/RGBD/color/{i:05}.jpg")).unwrap(), "").unwrap();
        let depth = io::read_image(data_file(&format!("open3d/RGBD/depth/{i:05}.png")).unwrap(), "").unwrap();
        let camera = poses.get(i).unwrap();
        let frame = RgbdImage::from_color_and_depth(&color, &depth, &options).unwrap();
        volume.integrate(&frame, &camera.intrinsic, &camera.extrinsic).unwrap();
    }
    let mesh = volume.extract_triangle_mesh().unwrap();
    let (v, t) = (mesh.num_vertices().unwrap() as f64, mesh.num_triangles().unwrap() as f64);
    assert!((v - 147927.0).abs() < 0.002 * 147927.0, "{v}");
    assert!((t - 280605.0).abs() < 0.002 * 280605.0, "{t}");
}

#[test]
fn errors() {
    let err = TSDFVolume::new_scalable(0.0, 0.04, TSDFVolumeColorType::NoColor, 16, 4).err().unwrap();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    let mut volume = TSDFVolume::new_scalable(0.01, 0.04, TSDFVolumeColorType::Rgb8, 16, 4).unwrap();
    let err = volume.integrate(&plane_frame(false), &small(), &IDENTITY).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    assert_eq!(volume.extract_volume_tsdf().unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(volume.block_count().unwrap(), 0);
}
