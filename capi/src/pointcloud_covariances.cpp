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

// Eigen::Matrix3d is column-major and covariances are symmetric, but set_covariances accepts any matrix:
// convert explicitly rather than rely on symmetry.
namespace {

void to_row_major(const Eigen::Matrix3d& m, double* out) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = m(r, c);
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_pointcloud_has_covariances(const o3d_pointcloud_t* pc, int32_t* out) {
    return guard(__func__, [&] {
        const PointCloud& cloud = require(pc, "pc")->cloud;
        require(out, "out");
        *out = cloud.has_covariances() ? 1 : 0;
    });
}

O3D_API o3d_status o3d_pointcloud_set_covariances(o3d_pointcloud_t* pc, const double* data, size_t n) {
    return guard(__func__, [&] {
        PointCloud& cloud = require(pc, "pc")->cloud;
        if (n > 0 && !data) throw o3d::InvalidArgument("data is NULL but n = " + std::to_string(n));
        std::vector<Eigen::Matrix3d> covariances(n);
        for (size_t i = 0; i < n; ++i)
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) covariances[i](r, c) = data[9 * i + static_cast<size_t>(3 * r + c)];
        cloud.covariances = std::move(covariances);
    });
}

O3D_API o3d_status o3d_pointcloud_get_covariances(const o3d_pointcloud_t* pc, double* out, size_t capacity,
                                                  size_t* out_n) {
    return guard(__func__, [&] {
        const PointCloud& cloud = require(pc, "pc")->cloud;
        require(out_n, "out_n");
        const size_t n = cloud.covariances.size();
        *out_n = n;
        if (!out) return;
        if (capacity < n)
            throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " matrices but " +
                                      std::to_string(n) + " are needed");
        for (size_t i = 0; i < n; ++i) to_row_major(cloud.covariances[i], out + 9 * i);
    });
}

O3D_API o3d_status o3d_pointcloud_covariances_view(const o3d_pointcloud_t* pc, const double** out_data,
                                                   size_t* out_n) {
    return guard(__func__, [&] {
        const PointCloud& cloud = require(pc, "pc")->cloud;
        require(out_data, "out_data");
        require(out_n, "out_n");
        // Row-major = column-major only for symmetric matrices: a zero-copy view is exact for those only.
        for (size_t i = 0; i < cloud.covariances.size(); ++i)
            if (cloud.covariances[i] != cloud.covariances[i].transpose())
                throw o3d::InvalidArgument("covariance " + std::to_string(i) +
                                           " is not symmetric; a row-major view needs o3d_pointcloud_get_covariances");
        *out_data = cloud.covariances.empty() ? nullptr : cloud.covariances[0].data();
        *out_n = cloud.covariances.size();
    });
}

O3D_API o3d_status o3d_pointcloud_estimate_covariances(o3d_pointcloud_t* pc, const o3d_search_param_t* param) {
    return guard(__func__, [&] {
        PointCloud& cloud = require(pc, "pc")->cloud;
        o3d::geometry::estimate_covariances(cloud, o3d::capi::to_search_param(param));
    });
}

}  // extern "C"
