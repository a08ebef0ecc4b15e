//! The scene reconstruction system (Open3D's reconstruction_system, Choi et al. 2015): a folder of
//! RGB-D frames and a JSON config in Open3D's layout in, `scene/integrated.ply` and
//! `scene/trajectory.log` out, one [`ReconstructionStage`] at a time. Each stage reads the previous
//! stages' files and resumes from its own (see `o3d/reconstruction.h`). The stage enum and the
//! options are generated from the C header.
use std::path::Path;

use o3d_sys as sys;

use crate::error::{check, Result};
use crate::io::c_path;
use crate::progress::progress_pair;
use crate::util::{c_enum, options};

include!("generated/reconstruction.rs");

progress_pair! {
    /// Run one stage of the system on the dataset `config` names (Open3D's `run_system.py --make`,
    /// `--register`, `--refine`, `--integrate`). Errors name the stage and the frame or fragment.
    pub fn run_stage;
    /// As [`run_stage`], reporting the fraction of the stage done to `progress` on this thread.
    /// Return `ControlFlow::Break(())` to stop with [`crate::ErrorCode::Cancelled`]; finished
    /// outputs are kept, so running the stage again resumes.
    pub fn run_stage_with_progress(
        config: &Path,
        stage: ReconstructionStage,
        options: &ReconstructionOptions,
    ) -> Result<()>;
    |callback, user_data| {
        let path = c_path(config)?;
        let mut opts = options.to_raw()?;
        (opts.progress, opts.user_data) = (callback, user_data);
        // SAFETY: a NUL-terminated path and an options struct that live for the call.
        check(unsafe { sys::o3d_reconstruction_run_stage(path.as_ptr(), stage.raw(), &opts) })
    }
}
