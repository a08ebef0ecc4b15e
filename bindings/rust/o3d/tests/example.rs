//! The examples run on the real data (built by cargo for this test) and report what they did.
mod common;

use std::process::Command;

#[test]
fn figure1_example_runs() {
    let Some(input) = common::data_file("open3d/Feature/cloud_bin_0.pcd") else { return };
    // Cargo builds examples before integration tests; find it next to this test binary.
    let exe = std::env::current_exe().unwrap().parent().unwrap().parent().unwrap().join("examples/figure1");
    if !exe.exists() {
        panic!("{} was not built (run plain `cargo test`, or `cargo build --examples` first)", exe.display());
    }
    let dir = common::TempDir::new("example");
    let out = dir.path("down.pcd");
    let run = Command::new(&exe).arg(&input).arg(&out).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "stdout: {stdout}\nstderr: {}", String::from_utf8_lossy(&run.stderr));
    assert!(stdout.contains("read 3903 points"), "{stdout}");
    assert!(stdout.contains("estimate_normals"), "{stdout}");
    let back = o3d::io::read_point_cloud(&out, "auto", &Default::default()).unwrap();
    assert!(back.has_normals().unwrap() && !back.is_empty() && back.len() < 3903);

    // Usage error and a missing input are reported with a non-zero status.
    assert_eq!(Command::new(&exe).output().unwrap().status.code(), Some(2));
    let missing = Command::new(&exe).arg(dir.path("none.pcd")).arg(&out).output().unwrap();
    assert_eq!(missing.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("Io"));
}

#[test]
fn rgbd_example_runs() {
    let (Some(color), Some(depth)) =
        (common::data_file("open3d/RGBD/color/00000.jpg"), common::data_file("open3d/RGBD/depth/00000.png"))
    else {
        return;
    };
    let exe = std::env::current_exe().unwrap().parent().unwrap().parent().unwrap().join("examples/rgbd_to_point_cloud");
    if !exe.exists() {
        panic!("{} was not built (run plain `cargo test`, or `cargo build --examples` first)", exe.display());
    }
    let dir = common::TempDir::new("rgbd-example");
    let out = dir.path("frame.ply");
    let run = Command::new(&exe).arg(&color).arg(&depth).arg(&out).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "stdout: {stdout}\nstderr: {}", String::from_utf8_lossy(&run.stderr));
    // Open3D 0.20 keeps 267129 points of this frame (tools/reference/record_rgbd.py, "rgbd_rgb").
    assert!(stdout.contains("wrote 267129 colored points"), "{stdout}");
    let back = o3d::io::read_point_cloud(&out, "auto", &Default::default()).unwrap();
    assert_eq!(back.len(), 267_129);
    assert!(back.has_colors().unwrap());
    // Flipped to y-up: the scene lies in front of the camera at negative z.
    assert!(back.points().iter().all(|p| p[2] < 0.0));
    assert_eq!(Command::new(&exe).output().unwrap().status.code(), Some(2));
}

#[test]
fn global_registration_example_runs() {
    let (Some(source), Some(target)) =
        (common::data_file("open3d/Feature/cloud_bin_0.pcd"), common::data_file("open3d/Feature/cloud_bin_1.pcd"))
    else {
        return;
    };
    let exe = std::env::current_exe().unwrap().parent().unwrap().parent().unwrap().join("examples/global_registration");
    if !exe.exists() {
        panic!("{} was not built (run plain `cargo test`, or `cargo build --examples` first)", exe.display());
    }
    let run = Command::new(&exe).arg(&source).arg(&target).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "stdout: {stdout}\nstderr: {}", String::from_utf8_lossy(&run.stderr));
    assert!(stdout.contains("read 3903 + 3458 points"), "{stdout}");
    assert!(stdout.contains("FPFH 33 x "), "{stdout}");
    // The refined result undoes the 60 degree motion to the scans' own agreement (~0.4 deg).
    let line = stdout.lines().find(|l| l.starts_with("ICP refine")).unwrap_or_else(|| panic!("{stdout}"));
    let deg: f64 = line.split("off by ").nth(1).unwrap().split(" deg").next().unwrap().trim().parse().unwrap();
    assert!(deg < 1.5, "{line}");
    assert_eq!(Command::new(&exe).output().unwrap().status.code(), Some(2));
    assert_eq!(Command::new(&exe).arg(&source).arg(&target).arg("-1").output().unwrap().status.code(), Some(2));
}
