// SPDX-License-Identifier: MIT
#pragma once
/// @file fragment_clouds.h
/// @brief Reading the fragment clouds stage 1 wrote, for the registration stages.
#include <string>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/reconstruction/config.h"
#include "o3d/reconstruction/stage_runner.h"

namespace o3d::reconstruction {

/// @brief Fragment clouds 0 .. n-1 (one progress unit each). A missing one names the "make fragments" stage.
std::vector<geometry::PointCloud> read_fragment_clouds(const Config& config, int n, int num_threads,
                                                       StageProgress& progress, const char* stage);

}  // namespace o3d::reconstruction
