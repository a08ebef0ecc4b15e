//! Built against the packaged `o3d` crate and an installed libo3d: down-sample a synthetic cloud.
use o3d::{ErrorCode, PointCloud};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A 10 x 10 x 10 grid with spacing 1.
    let grid: Vec<[f64; 3]> = (0..1000).map(|i| [(i % 10) as f64, ((i / 10) % 10) as f64, (i / 100) as f64]).collect();
    let cloud = PointCloud::from_points(&grid)?;
    // As Open3D, voxels start half a voxel below the minimum: 0 | 1 2 | 3 4 | ... | 9 gives 6 per axis.
    let down = cloud.voxel_down_sample(2.0)?;
    println!("o3d {}: {} points -> {} after voxel_down_sample(2)", o3d::version(), cloud.len(), down.len());
    if down.len() != 216 {
        return Err(format!("expected 216 points, got {}", down.len()).into());
    }
    // Bad input is an Err, not a crash.
    match cloud.voxel_down_sample(-1.0) {
        Err(e) if e.code == ErrorCode::InvalidArgument => println!("voxel_down_sample(-1) -> Err: {e}"),
        Err(e) => return Err(format!("expected InvalidArgument, got {e}").into()),
        Ok(c) => return Err(format!("expected an error, got a cloud of {} points", c.len()).into()),
    }
    Ok(())
}
