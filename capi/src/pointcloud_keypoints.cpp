// SPDX-License-Identifier: MIT
// C API: pointcloud.h's consistent normal orientation, duplicate removal and ISS keypoints.
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/duplicate_points.h"
#include "o3d/geometry/iss_keypoints.h"
#include "o3d/geometry/normal_orientation.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/pointcloud.h"

using o3d::capi::guard;
using o3d::capi::require;

namespace {

// Open3D's keypoint.compute_iss_keypoints defaults.
constexpr o3d_iss_options_t kIssDefaults = {sizeof(o3d_iss_options_t), 0.0, 0.0, 0.975, 0.975, 5, 0};

}  // namespace

extern "C" {

O3D_API o3d_status o3d_pointcloud_orient_normals_consistent_tangent_plane(o3d_pointcloud_t* pc, o3d_count k,
                                                                         double lambda, double cos_alpha_tol) {
    return guard(__func__, [&] {
        auto& cloud = require(pc, "pc")->cloud;
        o3d::geometry::orient_normals_consistent_tangent_plane(cloud, k, lambda, cos_alpha_tol);
    });
}

O3D_API o3d_status o3d_pointcloud_remove_duplicated_points(o3d_pointcloud_t* pc) {
    return guard(__func__, [&] { o3d::geometry::remove_duplicated_points(require(pc, "pc")->cloud); });
}

O3D_API o3d_status o3d_iss_options_init(o3d_iss_options_t* opts, uint32_t struct_size) {
    return guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kIssDefaults, "opts"); });
}

O3D_API o3d_status o3d_pointcloud_compute_iss_keypoints(o3d_pointcloud_t** out, int32_t* out_indices,
                                                        size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc,
                                                        const o3d_iss_options_t* opts) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        if (out_indices) require(out_n, "out_n");
        const auto& cloud = require(pc, "pc")->cloud;
        const o3d_iss_options_t o = o3d::capi::read_options(opts, kIssDefaults, "opts");
        o3d::geometry::IssOptions options;
        options.salient_radius = o.salient_radius;
        options.non_max_radius = o.non_max_radius;
        options.gamma_21 = o.gamma_21;
        options.gamma_32 = o.gamma_32;
        options.min_neighbors = o.min_neighbors;
        options.num_threads = o3d::capi::to_num_threads(o.num_threads);
        const std::vector<int64_t> indices = o3d::geometry::compute_iss_keypoint_indices(cloud, options);
        // Indices first, so BUFFER_TOO_SMALL leaves *out NULL.
        const std::vector<int32_t> narrow(indices.begin(), indices.end());
        o3d::capi::copy_out(narrow.data(), narrow.size(), out_indices, capacity, out_n);
        auto handle = std::make_unique<o3d_pointcloud>();
        handle->cloud = o3d::geometry::select_by_index(cloud, indices);
        *out = handle.release();
    });
}

}  // extern "C"
