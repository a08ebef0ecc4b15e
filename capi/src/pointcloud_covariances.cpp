// SPDX-License-Identifier: MIT
// C API: the per-point covariances of pointcloud.h over o3d::geometry.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/point_cloud_covariances.h"
#include "o3d/pointcloud.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::geometry::PointCloud;

extern "C" {

O3D_API o3d_status o3d_pointcloud_estimate_covariances(o3d_pointcloud_t* pc, const o3d_search_param_t* param) {
    return guard(__func__, [&] {
        PointCloud& cloud = require(pc, "pc")->cloud;
        o3d::geometry::estimate_covariances(cloud, o3d::capi::to_search_param(param));
    });
}

}  // extern "C"
