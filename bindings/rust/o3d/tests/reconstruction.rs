//! The reconstruction system from Rust: a stage run on a small dataset written here (three frames of a
//! textured plane 1 m away, the camera sliding 1 cm a frame), progress that rises to 1 and cancels,
//! and errors that name the stage to run first. (The known-trajectory run is
//! tests/capi/test_reconstruction.c; the living-room run is the Python test.)
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

use o3d::reconstruction::{run_stage, run_stage_with_progress, ReconstructionOptions, ReconstructionStage};
use o3d::{io, ErrorCode, Image, PinholeIntrinsic, PixelType};

const W: i32 = 96;
const H: i32 = 72;

/// A dataset below `folder` and the config that reconstructs it into `folder`/out.
fn write_dataset(folder: &Path) -> PathBuf {
    let _ = std::fs::remove_dir_all(folder);
    for sub in ["data/color", "data/depth"] {
        std::fs::create_dir_all(folder.join(sub)).unwrap();
    }
    for k in 0..3 {
        let mut rgb = vec![0u8; (3 * W * H) as usize];
        for v in 0..H {
            for u in 0..W {
                let x = (u as f64 - W as f64 / 2.0) / 80.0 + 0.01 * k as f64;
                let y = (v as f64 - H as f64 / 2.0) / 80.0;
                for c in 0..3 {
                    let value = 128.0 + 100.0 * (9.0 * x + 2.0 * c as f64).sin() * (7.0 * y - c as f64).cos();
                    rgb[(3 * (v * W + u) + c) as usize] = value as u8;
                }
            }
        }
        let color = Image::from_bytes(W, H, 3, PixelType::U8, &rgb).unwrap();
        let depth = Image::from_u16(W, H, &vec![1000u16; (W * H) as usize]).unwrap();
        io::write_image(folder.join(format!("data/color/{k:05}.png")), &color, "", None).unwrap();
        io::write_image(folder.join(format!("data/depth/{k:05}.png")), &depth, "", None).unwrap();
    }
    let intrinsic = PinholeIntrinsic::new(W, H, 80.0, 80.0, 47.5, 35.5);
    io::write_pinhole_camera_intrinsic(folder.join("intrinsic.json"), &intrinsic).unwrap();
    let config = folder.join("config.json");
    let root = folder.display();
    std::fs::write(
        &config,
        format!(
            "{{\"path_dataset\": \"{root}/data\", \"path_intrinsic\": \"{root}/intrinsic.json\", \
             \"path_output\": \"{root}/out\", \"n_frames_per_fragment\": 3, \"n_keyframes_per_n_frame\": 1, \
             \"tsdf_cubic_size\": 4.0}}"
        ),
    )
    .unwrap();
    config
}

#[test]
fn options_come_from_the_c_header() {
    let o = ReconstructionOptions::default();
    assert!(o.resume);
    assert_eq!(o.num_threads, 0);
}

#[test]
fn make_fragments_reports_progress_and_cancels() {
    let folder = std::env::temp_dir().join("o3d_rust_reconstruction");
    let config = write_dataset(&folder);
    let mut seen = Vec::new();
    run_stage_with_progress(&config, ReconstructionStage::MakeFragments, &ReconstructionOptions::default(), |f| {
        seen.push(f);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(*seen.last().unwrap(), 1.0);
    assert!(seen.windows(2).all(|w| w[0] <= w[1]));
    let fragment = folder.join("out/fragments/fragment_000.ply");
    assert!(fragment.exists());

    let redo = ReconstructionOptions { resume: false, ..Default::default() };
    let err = run_stage_with_progress(&config, ReconstructionStage::MakeFragments, &redo, |_| ControlFlow::Break(()))
        .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled);
    assert!(fragment.exists(), "finished outputs stay");
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn errors_name_the_stage_to_run_first() {
    let folder = std::env::temp_dir().join("o3d_rust_reconstruction_errors");
    let config = write_dataset(&folder);
    let err = run_stage(&config, ReconstructionStage::IntegrateScene, &ReconstructionOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::Io);
    assert!(err.to_string().contains("run the \"refine registration\" stage first"), "{err}");
    std::fs::remove_dir_all(&folder).unwrap();
}
