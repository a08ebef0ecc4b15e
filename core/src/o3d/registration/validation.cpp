// SPDX-License-Identifier: MIT
#include "o3d/registration/validation.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::registration::detail {

void check_registration_inputs(const geometry::PointCloud& source, const geometry::PointCloud& target,
                               double max_correspondence_distance, const Eigen::Matrix4d& transformation,
                               int num_threads) {
    if (!source.has_points()) throw InvalidArgument("source point cloud is empty");
    if (!target.has_points()) throw InvalidArgument("target point cloud is empty");
    if (!(max_correspondence_distance > 0.0))  // also rejects NaN
        throw InvalidArgument("max_correspondence_distance must be > 0, got " +
                              std::to_string(max_correspondence_distance));
    if (!transformation.allFinite()) throw InvalidArgument("transformation has a non-finite entry");
    if (num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(num_threads));
}

}  // namespace o3d::registration::detail
