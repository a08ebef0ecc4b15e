//! Figure 2 in Rust: a point cloud and a mesh shown together in the viewer, the view turning once around
//! them in `frames` steps (an animation callback), each frame captured as a PNG. The window is hidden, so
//! this runs headless (EGL).
//!
//! Usage: `cargo run --example figure2 -- <output folder> [frames (default 24)]`; prints each PNG's path.
use std::cell::Cell;
use std::f64::consts::PI;
use std::path::PathBuf;
use std::process::ExitCode;
use std::rc::Rc;

use o3d::visualization::Visualizer;
use o3d::TriangleMesh;

/// ViewControl.rotate turns 0.003 rad per pixel.
const RAD_PER_PIXEL: f64 = 0.003;

fn run(out: PathBuf, frames: usize) -> o3d::Result<()> {
    std::fs::create_dir_all(&out)
        .map_err(|e| o3d::Error::new(o3d::ErrorCode::Io, format!("cannot create {}: {e}", out.display())))?;
    // The mesh: a shaded sphere. The cloud: 20000 points sampled from a torus around it.
    let mut sphere = TriangleMesh::create_sphere(0.6, 40)?;
    sphere.compute_vertex_normals(true)?.paint_uniform_color([0.9, 0.6, 0.2])?;
    let mut cloud = TriangleMesh::create_torus(1.2, 0.25, 60, 20)?.sample_points_uniformly(20000, false, 7)?;
    cloud.paint_uniform_color([0.2, 0.4, 0.8])?;

    let mut vis = Visualizer::new()?;
    vis.create_window("figure2", 640, 480, -1, -1, false)?;
    vis.add_geometry("cloud", &cloud, true)?;
    vis.add_geometry("sphere", &sphere, true)?;
    vis.rotate(0.0, -150.0)?; // look from a little above
    let mut option = vis.render_option()?;
    option.point_size = 2.0; // the cloud's points apart, not a solid ring
    vis.set_render_option(&option)?;

    // Each loop: capture the frame, then turn by 1/frames of a full turn; close after the last one.
    let failed = Rc::new(Cell::new(None));
    let error = failed.clone();
    let mut frame = 0;
    vis.register_animation_callback(move |v| {
        let path = out.join(format!("frame_{frame:03}.png"));
        let step = v.capture_screen_image(&path).and_then(|()| v.rotate(2.0 * PI / RAD_PER_PIXEL / frames as f64, 0.0));
        let last = match step {
            Ok(()) => {
                println!("{}", path.display());
                frame + 1 == frames
            }
            Err(e) => {
                error.set(Some(e));
                true
            }
        };
        frame += 1;
        if last {
            v.close().ok();
        }
        true
    })?;
    vis.run()?;
    failed.take().map_or(Ok(()), Err)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    let frames = args.get(2).map_or(Ok(24), |n| n.parse::<usize>());
    match (args.len(), frames) {
        (2 | 3, Ok(frames)) if frames > 0 => match run(PathBuf::from(&args[1]), frames) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("figure2: {e}");
                ExitCode::FAILURE
            }
        },
        _ => {
            eprintln!("usage: {} <output folder> [frames > 0]", args.first().map_or("figure2", String::as_str));
            ExitCode::from(2)
        }
    }
}
