// SPDX-License-Identifier: MIT
// The reconstruction system over reconstruction.h: the stage enum (generated) and one stage call, run with the
// GIL released. The Python surface (run_system, the per-stage functions, the command line) is
// o3d/pipelines/reconstruction.py.
#include "registration_types.h"

namespace o3dpy {

void define_reconstruction(py::module_& m) {
    def_enum<ReconstructionStage>(m);
    m.def(
        "_reconstruction_run_stage",
        [](const std::string& config_path, ReconstructionStage stage, bool resume, int32_t num_threads,
           py::object progress) {
            o3d_reconstruction_options_t o = init_of(&o3d_reconstruction_options_init);
            o.resume = resume ? 1 : 0;
            o.num_threads = num_threads;
            Progress ctx(std::move(progress));
            o.progress = &progress_trampoline;
            o.user_data = &ctx;
            o3d_status status;
            {
                py::gil_scoped_release release;
                status = o3d_reconstruction_run_stage(config_path.c_str(),
                                                      static_cast<o3d_reconstruction_stage>(stage), &o);
            }
            ctx.rethrow();
            check(status);
        },
        py::arg("config_path"), py::arg("stage"), py::arg("resume"), py::arg("num_threads"), py::arg("progress"));
}

}  // namespace o3dpy
