// SPDX-License-Identifier: MIT
#include "o3d/reconstruction/reconstruction.h"

#include "o3d/reconstruction/stage_runner.h"

namespace o3d::reconstruction {

const char* stage_name(Stage stage) {
    switch (stage) {
        case Stage::MakeFragments: return "make fragments";
        case Stage::RegisterFragments: return "register fragments";
        case Stage::RefineRegistration: return "refine registration";
        case Stage::IntegrateScene: return "integrate scene";
        case Stage::ColorMap: return "color map";
    }
    return "unknown stage";
}

void run_stage(Stage stage, const Config& config, const StageOptions& options) {
    if (options.num_threads < 0) throw InvalidArgument("num_threads must be >= 0");
    with_context(stage_name(stage), [&] {
        switch (stage) {
            case Stage::MakeFragments: return make_fragments(config, options);
            case Stage::RegisterFragments: return register_fragments(config, options);
            case Stage::RefineRegistration: return refine_registration(config, options);
            case Stage::IntegrateScene: return integrate_scene(config, options);
            case Stage::ColorMap: return color_map_scene(config, options);
        }
        throw InvalidArgument("unknown stage " + std::to_string(static_cast<int>(stage)));
    });
}

}  // namespace o3d::reconstruction
