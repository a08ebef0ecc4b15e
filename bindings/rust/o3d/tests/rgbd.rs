//! Cameras, RGB-D images and depth back-projection against the pinhole model.
mod common;

use common::*;
use o3d::io;
use o3d::{
    CameraTrajectory, DepthToCloudOptions, ErrorCode, Image, IntrinsicPreset, PinholeCameraParameters,
    PinholeIntrinsic, PixelType, PointCloud, RgbdFormat, RgbdImage, RgbdOptions,
};

const W: i32 = 4;
const H: i32 = 3;

fn intrinsic() -> PinholeIntrinsic {
    PinholeIntrinsic::new(W, H, 2.0, 4.0, 1.5, 1.0)
}

/// Raw depth in mm at (u, v); pixel (1, 1) is invalid (0).
fn depth_mm(u: i32, v: i32) -> u16 {
    if (u, v) == (1, 1) {
        0
    } else {
        1000 + 250 * (u + v) as u16
    }
}

fn depth_image() -> Image {
    let values: Vec<u16> = (0..H).flat_map(|v| (0..W).map(move |u| depth_mm(u, v))).collect();
    Image::from_u16(W, H, &values).unwrap()
}

/// The pinhole model: ((u - cx) z / fx, (v - cy) z / fy, z), rows then columns, valid pixels only.
/// As in Open3D 0.20, a depth equal to `trunc` is dropped too (create_from_depth_image with
/// depth_trunc=1.5 keeps 1.0 but not 1.5).
fn expected_points(stride: i32, trunc: f64) -> Vec<[f64; 3]> {
    let k = intrinsic();
    let mut out = Vec::new();
    for v in (0..H).step_by(stride as usize) {
        for u in (0..W).step_by(stride as usize) {
            let z = depth_mm(u, v) as f64 / 1000.0;
            if z > 0.0 && z < trunc {
                out.push([(u as f64 - k.cx) * z / k.fx, (v as f64 - k.cy) * z / k.fy, z]);
            }
        }
    }
    out
}

fn assert_close(a: &[[f64; 3]], b: &[[f64; 3]], tol: f64) {
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(b) {
        for i in 0..3 {
            assert!((p[i] - q[i]).abs() <= tol, "{p:?} vs {q:?}");
        }
    }
}

#[test]
fn intrinsic_presets_match_open3d() {
    let ps = PinholeIntrinsic::preset(IntrinsicPreset::PrimeSenseDefault).unwrap();
    assert_eq!(ps, PinholeIntrinsic::new(640, 480, 525.0, 525.0, 319.5, 239.5));
    let kd = PinholeIntrinsic::preset(IntrinsicPreset::Kinect2DepthDefault).unwrap();
    assert_eq!(kd, PinholeIntrinsic::new(512, 424, 365.456, 365.456, 254.878, 205.395));
    let kc = PinholeIntrinsic::preset(IntrinsicPreset::Kinect2ColorDefault).unwrap();
    assert_eq!(kc, PinholeIntrinsic::new(1920, 1080, 1059.9718, 1059.9718, 975.7193, 545.9533));
    assert_eq!(ps.intrinsic_matrix(), [[525.0, 0.0, 319.5], [0.0, 525.0, 239.5], [0.0, 0.0, 1.0]]);
}

fn pose(tx: f64) -> [[f64; 4]; 4] {
    [[1.0, 0.0, 0.0, tx], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
}

#[test]
fn trajectory_holds_poses() {
    let mut traj = CameraTrajectory::new().unwrap();
    assert!(traj.is_empty().unwrap());
    traj.push(&intrinsic(), &pose(1.0)).unwrap();
    traj.push(&PinholeIntrinsic::preset(IntrinsicPreset::PrimeSenseDefault).unwrap(), &pose(2.0)).unwrap();
    assert_eq!(traj.len().unwrap(), 2);
    let second = traj.get(1).unwrap();
    assert_eq!(second.extrinsic, pose(2.0));
    assert_eq!(second.intrinsic.width, 640);
    assert_eq!(traj.parameters().unwrap()[0], PinholeCameraParameters { intrinsic: intrinsic(), extrinsic: pose(1.0) });
    assert_eq!(traj.get(2).unwrap_err().code, ErrorCode::InvalidArgument);
    let mut bad = pose(0.0);
    bad[3][0] = 1.0;
    assert_eq!(traj.push(&intrinsic(), &bad).unwrap_err().code, ErrorCode::InvalidArgument);
    traj.clear().unwrap();
    assert_eq!(traj.len().unwrap(), 0);
}

#[test]
fn camera_files_round_trip() {
    let dir = TempDir::new("camera");
    let k = intrinsic();
    io::write_pinhole_camera_intrinsic(dir.path("k.json"), &k).unwrap();
    assert_eq!(io::read_pinhole_camera_intrinsic(dir.path("k.json")).unwrap(), k);

    let params = PinholeCameraParameters { intrinsic: k, extrinsic: pose(0.25) };
    io::write_pinhole_camera_parameters(dir.path("p.json"), &params).unwrap();
    assert_eq!(io::read_pinhole_camera_parameters(dir.path("p.json")).unwrap(), params);

    let mut traj = CameraTrajectory::new().unwrap();
    traj.push(&k, &pose(1.0)).unwrap();
    traj.push(&k, &pose(-2.0)).unwrap();
    io::write_pinhole_camera_trajectory(dir.path("t.json"), &traj, "auto").unwrap();
    let back = io::read_pinhole_camera_trajectory(dir.path("t.json"), "auto").unwrap();
    assert_eq!(back.parameters().unwrap(), traj.parameters().unwrap());
    // .log keeps only the poses; the intrinsic comes back as the PrimeSense default.
    io::write_pinhole_camera_trajectory(dir.path("t.log"), &traj, "log").unwrap();
    let log = io::read_pinhole_camera_trajectory(dir.path("t.log"), "auto").unwrap();
    assert_eq!(log.len().unwrap(), 2);
    for i in 0..2 {
        let got = log.get(i).unwrap();
        let want = traj.get(i).unwrap().extrinsic;
        for (got_row, want_row) in got.extrinsic.iter().zip(&want) {
            for (g, w) in got_row.iter().zip(want_row) {
                assert!((g - w).abs() < 1e-9);
            }
        }
        assert_eq!(got.intrinsic.width, 640);
    }
    assert!(io::read_pinhole_camera_intrinsic(dir.path("missing.json")).is_err());
    std::fs::write(dir.path("broken.json"), "{ not json").unwrap();
    assert!(io::read_pinhole_camera_intrinsic(dir.path("broken.json")).is_err());
}

#[test]
fn depth_back_projection_matches_the_pinhole_model() {
    let depth = depth_image();
    let pcd = PointCloud::create_from_depth_image(&depth, &intrinsic(), None, &Default::default()).unwrap();
    assert_close(pcd.points(), &expected_points(1, f64::INFINITY), 1e-12);

    // Float depth in metres gives the same cloud.
    let metres: Vec<f32> = (0..H).flat_map(|v| (0..W).map(move |u| depth_mm(u, v) as f32 / 1000.0)).collect();
    let float_depth = Image::from_f32(W, H, &metres).unwrap();
    let pcd_f = PointCloud::create_from_depth_image(&float_depth, &intrinsic(), None, &Default::default()).unwrap();
    assert_close(pcd_f.points(), &expected_points(1, f64::INFINITY), 1e-6);

    // Stride and truncation.
    let opts = DepthToCloudOptions { stride: 2, depth_trunc: 1.5, ..Default::default() };
    let sparse = PointCloud::create_from_depth_image(&depth, &intrinsic(), None, &opts).unwrap();
    assert_close(sparse.points(), &expected_points(2, 1.5), 1e-12);

    // World-to-camera extrinsic translating by t: world points are camera points - t.
    let mut ext = pose(1.0);
    ext[1][3] = 2.0;
    ext[2][3] = 3.0;
    let world = PointCloud::create_from_depth_image(&depth, &intrinsic(), Some(&ext), &Default::default()).unwrap();
    let shifted: Vec<[f64; 3]> =
        expected_points(1, f64::INFINITY).iter().map(|p| [p[0] - 1.0, p[1] - 2.0, p[2] - 3.0]).collect();
    assert_close(world.points(), &shifted, 1e-12);

    // Organised output: one point per pixel, NaN for the invalid one.
    let organised = DepthToCloudOptions { project_valid_depth_only: false, ..Default::default() };
    let all = PointCloud::create_from_depth_image(&depth, &intrinsic(), None, &organised).unwrap();
    assert_eq!(all.len(), (W * H) as usize);
    assert!(all.points()[(W + 1) as usize].iter().all(|c| c.is_nan()));
}

#[test]
fn rgbd_back_projection_carries_colors() {
    let rgb: Vec<u8> = (0..W * H).flat_map(|i| [(10 * i) as u8, 100, 200]).collect();
    let color = Image::from_bytes(W, H, 3, PixelType::U8, &rgb).unwrap();
    let depth = depth_image();
    let opts = RgbdOptions { convert_rgb_to_intensity: false, depth_trunc: 10.0, ..Default::default() };
    let rgbd = RgbdImage::from_color_and_depth(&color, &depth, &opts).unwrap();
    assert_eq!(rgbd.color().unwrap().data().unwrap(), color.data().unwrap());
    let depth_m = rgbd.depth().unwrap();
    assert_eq!(depth_m.pixel_type().unwrap(), PixelType::F32);
    assert_eq!(depth_m.to_f32_vec().unwrap()[0], 1.0);

    let pcd = PointCloud::create_from_rgbd_image(&rgbd, &intrinsic(), None, true).unwrap();
    assert_close(pcd.points(), &expected_points(1, f64::INFINITY), 1e-6);
    let expected_colors: Vec<[f64; 3]> = (0..W * H)
        .filter(|&i| depth_mm(i % W, i / W) > 0)
        .map(|i| [(10 * i) as f64 / 255.0, 100.0 / 255.0, 200.0 / 255.0])
        .collect();
    assert_close(pcd.colors(), &expected_colors, 1e-6);

    // Intensity: one float channel, gray point colors.
    let gray = RgbdImage::from_color_and_depth(&color, &depth, &RgbdOptions::default()).unwrap();
    let intensity = gray.color().unwrap();
    assert_eq!((intensity.num_channels().unwrap(), intensity.pixel_type().unwrap()), (1, PixelType::F32));
    let gray_pcd = PointCloud::create_from_rgbd_image(&gray, &intrinsic(), None, true).unwrap();
    assert!(gray_pcd.colors().iter().all(|c| c[0] == c[1] && c[1] == c[2]));

    let redwood = RgbdImage::from_dataset_format(RgbdFormat::Redwood, &color, &depth, false).unwrap();
    assert_eq!(redwood.depth().unwrap().to_f32_vec().unwrap()[0], 1.0);
    let tum = RgbdImage::from_dataset_format(RgbdFormat::Tum, &color, &depth, false).unwrap();
    assert!((tum.depth().unwrap().to_f32_vec().unwrap()[0] - 0.2).abs() < 1e-6);
}

#[test]
fn rgbd_rejects_bad_input() {
    let depth = depth_image();
    let small = Image::new(2, 2, 3, PixelType::U8).unwrap();
    let err = RgbdImage::from_color_and_depth(&small, &depth, &Default::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    let rgb_depth = Image::new(W, H, 3, PixelType::U16).unwrap();
    let color = Image::new(W, H, 3, PixelType::U8).unwrap();
    assert!(RgbdImage::from_color_and_depth(&color, &rgb_depth, &Default::default()).is_err());
    let bad_scale = RgbdOptions { depth_scale: 0.0, ..Default::default() };
    assert!(RgbdImage::from_color_and_depth(&color, &depth, &bad_scale).is_err());

    let mut k = intrinsic();
    k.fx = 0.0;
    assert!(PointCloud::create_from_depth_image(&depth, &k, None, &Default::default()).is_err());
    let bad_stride = DepthToCloudOptions { stride: 0, ..Default::default() };
    assert!(PointCloud::create_from_depth_image(&depth, &intrinsic(), None, &bad_stride).is_err());
    let mut bad_ext = pose(0.0);
    bad_ext[0][0] = f64::NAN;
    assert!(PointCloud::create_from_depth_image(&depth, &intrinsic(), Some(&bad_ext), &Default::default()).is_err());
}

#[test]
fn shared_rgbd_frame_to_cloud() {
    let (Some(color), Some(depth)) =
        (data_file("open3d/RGBD/color/00000.jpg"), data_file("open3d/RGBD/depth/00000.png"))
    else {
        return;
    };
    let color = io::read_image(color, "auto").unwrap();
    let depth = io::read_image(depth, "auto").unwrap();
    let opts = RgbdOptions { convert_rgb_to_intensity: false, ..Default::default() };
    let rgbd = RgbdImage::from_color_and_depth(&color, &depth, &opts).unwrap();
    let k = PinholeIntrinsic::preset(IntrinsicPreset::PrimeSenseDefault).unwrap();
    let pcd = PointCloud::create_from_rgbd_image(&rgbd, &k, None, true).unwrap();
    // Open3D 0.20 keeps 267129 points (tools/reference/record_rgbd.py, "rgbd_rgb").
    assert_eq!(pcd.len(), 267_129);
    assert!(pcd.has_colors().unwrap());
    // Every point lies in front of the camera, within the 3 m truncation.
    assert!(pcd.points().iter().all(|p| p[2] > 0.0 && p[2] <= 3.0));
}
