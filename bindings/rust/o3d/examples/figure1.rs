//! Figure 1 in Rust: read a cloud, voxel-down-sample it (0.05), estimate normals (hybrid 0.1 / 30),
//! write it.
//!
//! Usage: `cargo run --example figure1 -- <input> <output>` (formats chosen by extension).
use std::process::ExitCode;
use std::time::Instant;

use o3d::io::{self, ReadOptions, WriteOptions};
use o3d::SearchParam;

fn run(input: &str, output: &str) -> o3d::Result<()> {
    let t0 = Instant::now();
    let pcd = io::read_point_cloud(input, "auto", &ReadOptions::default())?;
    println!("read {} points from {input}", pcd.len());
    let mut down = pcd.voxel_down_sample(0.05)?;
    println!("voxel_down_sample(0.05): {} -> {} points", pcd.len(), down.len());
    down.estimate_normals(SearchParam::Hybrid { radius: 0.1, max_nn: 30 })?;
    println!("estimate_normals(hybrid radius=0.1, max_nn=30) -> {} normals", down.normals().len());
    io::write_point_cloud(output, &down, "auto", &WriteOptions::default())?;
    println!(
        "wrote {} points with normals to {output} in {:.3} s (o3d {})",
        down.len(),
        t0.elapsed().as_secs_f64(),
        o3d::version()
    );
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        eprintln!("usage: {} <input> <output>", args.first().map_or("figure1", String::as_str));
        return ExitCode::from(2);
    }
    match run(&args[1], &args[2]) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("figure1: {e}");
            ExitCode::FAILURE
        }
    }
}
