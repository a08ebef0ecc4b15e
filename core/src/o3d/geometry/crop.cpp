// SPDX-License-Identifier: MIT
#include "o3d/geometry/crop.h"

#include <cmath>
#include <string>

#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

std::string vec_str(const Eigen::Vector3d& v) {
    return "(" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " + std::to_string(v.z()) + ")";
}

void check_box(const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound) {
    if (!min_bound.allFinite() || !max_bound.allFinite())
        throw InvalidArgument("crop box bounds must be finite, got min " + vec_str(min_bound) + " max " +
                              vec_str(max_bound));
    for (int a = 0; a < 3; ++a)
        if (!(max_bound[a] > min_bound[a]))
            throw InvalidArgument("crop box must have max_bound > min_bound on every axis (Open3D rejects empty "
                                  "or inverted boxes), got min " +
                                  vec_str(min_bound) + " max " + vec_str(max_bound));
}

}  // namespace

std::vector<int64_t> indices_in_aabb(const PointCloud& cloud, const Eigen::Vector3d& min_bound,
                                     const Eigen::Vector3d& max_bound) {
    check_box(min_bound, max_bound);
    std::vector<int64_t> indices;
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        if (p.x() >= min_bound.x() && p.x() <= max_bound.x() && p.y() >= min_bound.y() && p.y() <= max_bound.y() &&
            p.z() >= min_bound.z() && p.z() <= max_bound.z())
            indices.push_back(static_cast<int64_t>(i));
    }
    return indices;
}

PointCloud crop_aabb(const PointCloud& cloud, const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound,
                     bool invert) {
    return select_by_index(cloud, indices_in_aabb(cloud, min_bound, max_bound), invert);
}

}  // namespace o3d::geometry
