// SPDX-License-Identifier: MIT
// C API: the point-cloud smoothing filters of pointcloud.h (o3d::geometry::smooth_*).
#include <string>

#include "internal.h"
#include "o3d/geometry/point_cloud_smoothing.h"
#include "o3d/pointcloud.h"

using o3d::capi::emit_handle;
using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::require_out_handle;
using o3d::geometry::PointCloud;

namespace {

const PointCloud& cloud_of(const o3d_pointcloud_t* pc) { return require(pc, "pc")->cloud; }

/// Open3D's default for smooth_mls and smooth_bilateral: KDTreeSearchParamHybrid(radius=0.05, max_nn=30).
o3d::kdtree::SearchParam smoothing_search(const o3d_search_param_t* param) {
    if (!param) return {o3d::kdtree::SearchParam::Kind::Hybrid, 30, 0.05};
    return o3d::capi::to_search_param(param);
}

int to_int(o3d_count n, const char* name) {
    if (n < 0) throw o3d::InvalidArgument(std::string(name) + " must be >= 0, got " + std::to_string(n));
    return static_cast<int>(n);
}

}  // namespace

O3D_API o3d_status o3d_pointcloud_smooth_mls(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                             const o3d_search_param_t* param) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::smooth_mls(cloud_of(pc), smoothing_search(param)));
    });
}

O3D_API o3d_status o3d_pointcloud_smooth_laplacian(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                   o3d_count iterations, double lambda, o3d_count knn,
                                                   o3d_bool use_fixed_neighborhoods) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::smooth_laplacian(cloud_of(pc), to_int(iterations, "iterations"), lambda,
                                                         to_int(knn, "knn"), use_fixed_neighborhoods != 0));
    });
}

O3D_API o3d_status o3d_pointcloud_smooth_taubin(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                o3d_count iterations, double lambda, double mu, o3d_count knn,
                                                o3d_bool use_fixed_neighborhoods) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::smooth_taubin(cloud_of(pc), to_int(iterations, "iterations"), lambda, mu,
                                                      to_int(knn, "knn"), use_fixed_neighborhoods != 0));
    });
}

O3D_API o3d_status o3d_pointcloud_smooth_bilateral(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                   const o3d_search_param_t* param, double sigma_s, double sigma_r) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::smooth_bilateral(cloud_of(pc), smoothing_search(param), sigma_s, sigma_r));
    });
}
