//! One RGB-D frame to a coloured point cloud (Open3D's RGBD tutorial): read color + depth (mm),
//! pair them (depth truncated at 3 m, RGB kept), back-project with the PrimeSense default
//! intrinsic, flip to a y-up view, write.
//!
//! Usage: `cargo run --example rgbd_to_point_cloud -- <color> <depth> <output>`.
use std::process::ExitCode;

use o3d::io::{self, WriteOptions};
use o3d::{IntrinsicPreset, PinholeIntrinsic, PointCloud, RgbdImage, RgbdOptions};

fn run(color: &str, depth: &str, output: &str) -> o3d::Result<()> {
    let color = io::read_image(color, "auto")?;
    let depth = io::read_image(depth, "auto")?;
    println!(
        "color {}x{}x{}, depth {}x{}",
        color.width()?,
        color.height()?,
        color.num_channels()?,
        depth.width()?,
        depth.height()?
    );
    let options = RgbdOptions { convert_rgb_to_intensity: false, ..Default::default() };
    let rgbd = RgbdImage::from_color_and_depth(&color, &depth, &options)?;
    let intrinsic = PinholeIntrinsic::preset(IntrinsicPreset::PrimeSenseDefault)?;
    let mut cloud = PointCloud::create_from_rgbd_image(&rgbd, &intrinsic, None, true)?;
    // The camera looks down +z with y down; flip so that the cloud is upright in a y-up viewer.
    let flip = [[1.0, 0.0, 0.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    cloud.transform(&flip)?;
    io::write_point_cloud(output, &cloud, "auto", &WriteOptions::default())?;
    println!("wrote {} colored points to {output}", cloud.len());
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 4 {
        eprintln!("usage: {} <color> <depth> <output>", args.first().map_or("rgbd_to_point_cloud", String::as_str));
        return ExitCode::from(2);
    }
    match run(&args[1], &args[2], &args[3]) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("rgbd_to_point_cloud: {e}");
            ExitCode::FAILURE
        }
    }
}
