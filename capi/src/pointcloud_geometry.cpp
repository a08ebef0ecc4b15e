// SPDX-License-Identifier: MIT
// C API: the point-cloud calls of pointcloud.h that describe a cloud's geometry without changing it: static
// covariances, planar patches, and down-sampling that traces each output point back to its inputs.
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/planar_patches.h"
#include "o3d/geometry/point_covariances_static.h"
#include "o3d/geometry/voxel_down_sample_trace.h"
#include "o3d/indexlists.h"
#include "o3d/pointcloud.h"

using o3d::capi::copy_out;
using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::require_out_handle;
using o3d::geometry::PointCloud;

namespace {

const PointCloud& cloud_of(const o3d_pointcloud_t* pc) { return require(pc, "pc")->cloud; }

const o3d_planar_patch_options_t kPlanarPatchDefaults{
    sizeof(o3d_planar_patch_options_t), 60.0, 75.0, 0.75, 0.0, 0,
    o3d_search_param_t{sizeof(o3d_search_param_t), O3D_SEARCH_KNN, 30, 0.0}, 0};

}  // namespace

O3D_API o3d_status o3d_pointcloud_estimate_point_covariances(double* out, size_t capacity, size_t* out_n,
                                                             const o3d_pointcloud_t* pc,
                                                             const o3d_search_param_t* param, int32_t num_threads) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const auto covariances = o3d::geometry::estimate_point_covariances(
            cloud_of(pc), o3d::capi::to_search_param(param), o3d::capi::to_num_threads(num_threads));
        std::vector<double> rows(9 * covariances.size());
        for (size_t i = 0; i < covariances.size(); ++i)
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) rows[9 * i + 3 * r + c] = covariances[i](r, c);
        copy_out(rows.data(), covariances.size(), out, capacity, out_n, 9);
    });
}

O3D_API o3d_status o3d_planar_patch_options_init(o3d_planar_patch_options_t* opts, uint32_t struct_size) {
    return guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kPlanarPatchDefaults, "opts"); });
}

O3D_API o3d_status o3d_pointcloud_detect_planar_patches(double* out, size_t capacity, size_t* out_n,
                                                        const o3d_pointcloud_t* pc,
                                                        const o3d_planar_patch_options_t* opts) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const PointCloud& cloud = cloud_of(pc);
        const auto o = o3d::capi::read_options(opts, kPlanarPatchDefaults, "opts");
        if (o.min_num_points < 0)
            throw o3d::InvalidArgument("opts.min_num_points must be >= 0, got " + std::to_string(o.min_num_points));
        const auto boxes = o3d::geometry::detect_planar_patches(
            cloud, o.normal_variance_threshold_deg, o.coplanarity_deg, o.outlier_ratio, o.min_plane_edge_length,
            static_cast<size_t>(o.min_num_points), o3d::capi::to_search_param(&o.search_param),
            o3d::capi::to_num_threads(o.num_threads));
        static_assert(sizeof(o3d_obb_t) == 15 * sizeof(double), "o3d_obb_t is 15 packed doubles");
        std::vector<double> rows(15 * boxes.size());
        for (size_t i = 0; i < boxes.size(); ++i) {
            double* row = rows.data() + 15 * i;
            for (int k = 0; k < 3; ++k) {
                row[k] = boxes[i].center(k);
                row[12 + k] = boxes[i].extent(k);
            }
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) row[3 + 3 * r + c] = boxes[i].R(r, c);
        }
        copy_out(rows.data(), boxes.size(), out, capacity, out_n, 15);
    });
}

O3D_API o3d_status o3d_pointcloud_voxel_down_sample_and_trace(o3d_pointcloud_t** out,
                                                              o3d_index_lists_t** out_cubic_ids,
                                                              o3d_index_lists_t** out_original_indices,
                                                              const o3d_pointcloud_t* pc, double voxel_size,
                                                              const double min_bound[3], const double max_bound[3],
                                                              o3d_bool approximate_class) {
    return guard(__func__, [&] {
        require_out_handle(out);
        require_out_handle(out_cubic_ids, "out_cubic_ids");
        require_out_handle(out_original_indices, "out_original_indices");
        auto trace = o3d::geometry::voxel_down_sample_and_trace(cloud_of(pc), voxel_size,
                                                                o3d::capi::vec3(min_bound, "min_bound"),
                                                                o3d::capi::vec3(max_bound, "max_bound"),
                                                                approximate_class != 0);
        std::vector<int> cubic_offsets(trace.cubic_ids.size() + 1), cubic_values(8 * trace.cubic_ids.size());
        for (size_t i = 0; i < trace.cubic_ids.size(); ++i) {
            cubic_offsets[i + 1] = static_cast<int>(8 * (i + 1));
            for (int k = 0; k < 8; ++k) cubic_values[8 * i + k] = trace.cubic_ids[i][k];
        }
        // Build every output before handing any out, so a failure leaves all three NULL.
        std::unique_ptr<o3d_index_lists_t> cubic(o3d::capi::make_index_lists(cubic_offsets, cubic_values));
        std::unique_ptr<o3d_index_lists_t> traced(o3d::capi::make_index_lists(trace.offsets, trace.indices));
        auto cloud = std::make_unique<o3d_pointcloud>();
        cloud->cloud = std::move(trace.cloud);
        *out = cloud.release();
        *out_cubic_ids = cubic.release();
        *out_original_indices = traced.release();
    });
}
