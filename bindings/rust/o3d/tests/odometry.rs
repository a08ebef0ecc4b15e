//! compute_rgbd_odometry: a frame onto itself, Open3D's result on its RGBD frames 0 -> 1 (open3d 0.20,
//! hybrid term, default options, PrimeSense intrinsics) and the errors.
mod common;

use common::*;
use o3d::io;
use o3d::odometry::{compute_rgbd_odometry, OdometryJacobian, OdometryOption};
use o3d::{ErrorCode, Image, PinholeIntrinsic, RgbdImage, RgbdOptions};

const W: i32 = 160;
const H: i32 = 120;

fn small() -> PinholeIntrinsic {
    PinholeIntrinsic::new(W, H, 130.0, 130.0, 79.5, 59.5)
}

fn float_image(f: impl Fn(f64, f64) -> f64) -> Image {
    let values: Vec<f32> =
        (0..H).flat_map(|v| (0..W).map(move |u| (u, v))).map(|(u, v)| f(u as f64, v as f64) as f32).collect();
    Image::from_f32(W, H, &values).unwrap()
}

/// A textured float intensity on a slanted plane of float depth (metres).
fn synthetic_frame() -> RgbdImage {
    let color = float_image(|u, v| 0.5 + 0.2 * (0.3 * u).sin() * (0.25 * v).cos() + 0.1 * (0.11 * (u + v)).sin());
    let depth = float_image(|u, v| 1.5 + 0.004 * u + 0.002 * v);
    let options = RgbdOptions { depth_scale: 1.0, ..Default::default() }; // already metres
    RgbdImage::from_color_and_depth(&color, &depth, &options).unwrap()
}

#[test]
fn a_frame_onto_itself_is_the_identity() {
    let frame = synthetic_frame();
    for j in [OdometryJacobian::ColorTerm, OdometryJacobian::HybridTerm] {
        let r = compute_rgbd_odometry(&frame, &frame, &small(), None, j, &OdometryOption::default()).unwrap();
        assert!(r.success, "{j:?}");
        for (i, row) in r.transformation.iter().enumerate() {
            for (k, x) in row.iter().enumerate() {
                let want = if i == k { 1.0 } else { 0.0 };
                assert!((x - want).abs() <= 1e-12, "{j:?}: T[{i}][{k}] = {x}");
            }
        }
        // Every pixel but the border the smoothing and the pyramid eat corresponds.
        assert!(r.information[3][3] > 0.9 * (W * H) as f64, "{}", r.information[3][3]);
    }
}

#[test]
fn open3d_frames_zero_to_one() {
    let mut frames = Vec::new();
    for i in 0..2 {
        let Some(color) = data_file(&format!("open3d/RGBD/color/0000{i}.jpg")) else { return };
        let Some(depth) = data_file(&format!("open3d/RGBD/depth/0000{i}.png")) else { return };
        let (color, depth) = (io::read_image(color, "").unwrap(), io::read_image(depth, "").unwrap());
        frames.push(RgbdImage::from_color_and_depth(&color, &depth, &RgbdOptions::default()).unwrap());
    }
    let primesense = PinholeIntrinsic::new(640, 480, 525.0, 525.0, 319.5, 239.5);
    let hybrid = OdometryJacobian::HybridTerm;
    let r =
        compute_rgbd_odometry(&frames[0], &frames[1], &primesense, None, hybrid, &OdometryOption::default()).unwrap();
    assert!(r.success);
    let t = [r.transformation[0][3], r.transformation[1][3], r.transformation[2][3]];
    for (got, want) in t.iter().zip([-0.0010704978, 0.0232280983, 0.0014059205]) {
        assert!((got - want).abs() <= 1e-5, "{t:?}");
    }
    assert!((r.information[3][3] - 252387.0).abs() <= 0.001 * 252387.0, "{}", r.information[3][3]);
    // Nothing within 0.3 m: no solution, no error, the identity.
    let mut near = OdometryOption::default();
    near.scalars.depth_max = 0.3;
    let none = compute_rgbd_odometry(&frames[0], &frames[1], &primesense, None, hybrid, &near).unwrap();
    assert!(!none.success);
    assert_eq!(none.transformation, o3d::registration::IDENTITY);
}

#[test]
fn errors() {
    let frame = synthetic_frame();
    let color = OdometryJacobian::default();
    let wrong_size = PinholeIntrinsic::new(2 * W, 2 * H, 130.0, 130.0, 79.5, 59.5);
    let e = compute_rgbd_odometry(&frame, &frame, &wrong_size, None, color, &OdometryOption::default()).unwrap_err();
    assert_eq!(e.code, ErrorCode::InvalidArgument);
    for levels in [vec![1; 9], vec![]] {
        let option = OdometryOption { iteration_number_per_pyramid_level: levels.clone(), ..Default::default() };
        let e = compute_rgbd_odometry(&frame, &frame, &small(), None, color, &option).unwrap_err();
        assert_eq!(e.code, ErrorCode::InvalidArgument, "{levels:?}");
    }
    let nan_init = [[f64::NAN; 4]; 4];
    let e = compute_rgbd_odometry(&frame, &frame, &small(), Some(&nan_init), color, &OdometryOption::default())
        .unwrap_err();
    assert_eq!(e.code, ErrorCode::InvalidArgument);
}
