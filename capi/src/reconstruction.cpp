// SPDX-License-Identifier: MIT
// C API of the reconstruction system (reconstruction.h).
#include "o3d/reconstruction.h"

#include "internal.h"
#include "o3d/reconstruction/reconstruction.h"

namespace {

namespace rec = o3d::reconstruction;

constexpr o3d_reconstruction_options_t kDefaults = {sizeof(o3d_reconstruction_options_t), 1, 0, nullptr, nullptr};

rec::Stage stage_of(o3d_reconstruction_stage stage) {
    if (stage < O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS || stage > O3D_RECONSTRUCTION_STAGE_COLOR_MAP)
        throw o3d::InvalidArgument("stage " + std::to_string(stage) + " is not an O3D_RECONSTRUCTION_STAGE_*");
    return static_cast<rec::Stage>(stage);
}

}  // namespace

O3D_API o3d_status o3d_reconstruction_options_init(o3d_reconstruction_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kDefaults, "opts"); });
}

O3D_API o3d_status o3d_reconstruction_run_stage(const char* config_path, o3d_reconstruction_stage stage,
                                                const o3d_reconstruction_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(config_path, "config_path");
        const rec::Stage which = stage_of(stage);
        const o3d_reconstruction_options_t o = o3d::capi::read_options(opts, kDefaults, "opts");
        rec::StageOptions options;
        options.resume = o.resume != 0;
        options.num_threads = o.num_threads;
        options.progress = o3d::capi::to_progress(o.progress, o.user_data);
        rec::run_stage(which, rec::read_config(config_path), options);
    });
}
