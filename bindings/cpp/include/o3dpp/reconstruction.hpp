// SPDX-License-Identifier: MIT
#pragma once
/// @file reconstruction.hpp
/// @brief The scene reconstruction system (Open3D's reconstruction_system): run_stage over a JSON config in
/// Open3D's layout, one ReconstructionStage at a time (enum and options generated from reconstruction.h).
#include <string>

#include "o3d/reconstruction.h"
#include "o3dpp/common.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/options.hpp"

namespace o3dpp {

/// @brief Run one stage on the dataset `config_path` names; each stage reads the previous stages' files and
/// resumes from its own. `options.progress` gets the fraction of the stage done (return false to cancel).
/// @throws o3dpp::Error naming the stage and the frame or fragment.
inline void run_reconstruction_stage(const std::string& config_path, ReconstructionStage stage,
                                     const ReconstructionOptions& options = {}) {
    check(detail::with_progress(options.to_c(), options.progress, [&](const auto* c) {
        return o3d_reconstruction_run_stage(config_path.c_str(), static_cast<o3d_reconstruction_stage>(stage), c);
    }));
}

}  // namespace o3dpp
