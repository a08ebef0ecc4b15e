// SPDX-License-Identifier: MIT
#include "o3d/geometry/point_covariances_static.h"

#include <utility>

#include "o3d/geometry/point_cloud_covariances.h"

namespace o3d::geometry {

std::vector<Eigen::Matrix3d> estimate_point_covariances(const PointCloud& cloud, const kdtree::SearchParam& param,
                                                        int num_threads) {
    // Only the points matter to the estimate: a points-only copy leaves the caller's cloud untouched.
    PointCloud scratch;
    scratch.points = cloud.points;
    estimate_covariances(scratch, param, num_threads);
    return std::move(scratch.covariances);
}

}  // namespace o3d::geometry
