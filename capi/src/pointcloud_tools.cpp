// SPDX-License-Identifier: MIT
// C API: the point-cloud tools of pointcloud.h (filters, segmentation, statistics) over o3d::geometry.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/crop.h"
#include "o3d/geometry/dbscan.h"
#include "o3d/geometry/outlier_removal.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/geometry/segment_plane.h"
#include "o3d/geometry/statistics.h"
#include "o3d/pointcloud.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::capi::require_finite;
using o3d::geometry::PointCloud;

namespace {

const PointCloud& nonempty_cloud(const o3d_pointcloud_t* pc) {
    const PointCloud& cloud = require(pc, "pc")->cloud;
    if (cloud.points.empty()) throw o3d::InvalidArgument("pc is empty");
    return cloud;
}

o3d_pointcloud_t** require_out(o3d_pointcloud_t** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

/// @brief Check the index buffer before any work: out_n is required; a non-NULL buffer must hold `count`.
void check_buffer(size_t count, const void* buffer, size_t capacity, size_t* out_n) {
    require(out_n, "out_n");
    *out_n = count;
    if (buffer && capacity < count)
        throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " items but " + std::to_string(count) +
                                  " are needed");
}

/// @brief Write int64 core indices as int32 with the copy-out convention.
void indices_out(const std::vector<int64_t>& indices, int32_t* out, size_t capacity, size_t* out_n) {
    require(out_n, "out_n");
    const std::vector<int32_t> narrow(indices.begin(), indices.end());  // a cloud holds < 2^31 points (KD-tree)
    o3d::capi::copy_out(narrow.data(), narrow.size(), out, capacity, out_n);
}

/// @brief Shared tail of the two outlier filters: indices out first (so BUFFER_TOO_SMALL leaves *out NULL),
/// then the kept cloud.
o3d_status filtered(o3d_pointcloud_t** out, const PointCloud& cloud, const std::vector<int64_t>& kept,
                    int32_t* out_indices, size_t capacity, size_t* out_n) {
    indices_out(kept, out_indices, capacity, out_n);
    auto handle = std::make_unique<o3d_pointcloud>();
    handle->cloud = o3d::geometry::select_by_index(cloud, kept);
    *out = handle.release();
    return O3D_OK;
}


}  // namespace

extern "C" {

O3D_API o3d_status o3d_pointcloud_remove_statistical_outlier(o3d_pointcloud_t** out, int32_t* out_indices,
                                                             size_t capacity, size_t* out_n,
                                                             const o3d_pointcloud_t* pc, int32_t nb_neighbors,
                                                             double std_ratio) {
    return guard(__func__, [&]() -> o3d_status {
        require_out(out);
        require(out_n, "out_n");
        const PointCloud& cloud = nonempty_cloud(pc);
        require_finite(std_ratio, "std_ratio");
        const auto kept = o3d::geometry::statistical_outlier_indices(cloud, nb_neighbors, std_ratio);
        return filtered(out, cloud, kept, out_indices, capacity, out_n);
    });
}

O3D_API o3d_status o3d_pointcloud_remove_radius_outlier(o3d_pointcloud_t** out, int32_t* out_indices, size_t capacity,
                                                        size_t* out_n, const o3d_pointcloud_t* pc, int32_t nb_points,
                                                        double radius) {
    return guard(__func__, [&]() -> o3d_status {
        require_out(out);
        require(out_n, "out_n");
        const PointCloud& cloud = nonempty_cloud(pc);
        require_finite(radius, "radius");
        const auto kept = o3d::geometry::radius_outlier_indices(cloud, nb_points, radius);
        return filtered(out, cloud, kept, out_indices, capacity, out_n);
    });
}

O3D_API o3d_status o3d_pointcloud_crop_aabb(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                            const double min_bound[3], const double max_bound[3], int32_t invert) {
    return guard(__func__, [&]() -> o3d_status {
        require_out(out);
        const PointCloud& cloud = nonempty_cloud(pc);
        const Eigen::Vector3d lo = vec3(min_bound, "min_bound"), hi = vec3(max_bound, "max_bound");
        auto handle = std::make_unique<o3d_pointcloud>();
        handle->cloud = o3d::geometry::crop_aabb(cloud, lo, hi, invert != 0);
        *out = handle.release();
        return O3D_OK;
    });
}

O3D_API o3d_status o3d_pointcloud_segment_plane(double out_plane[4], int32_t* out_indices, size_t capacity,
                                                size_t* out_n, const o3d_pointcloud_t* pc, double distance_threshold,
                                                int32_t ransac_n, int32_t num_iterations, double probability,
                                                uint64_t seed) {
    return guard(__func__, [&]() -> o3d_status {
        const PointCloud& cloud = nonempty_cloud(pc);
        require(out_plane, "out_plane");
        require(out_n, "out_n");
        require_finite(distance_threshold, "distance_threshold");
        require_finite(probability, "probability");
        const auto seg = o3d::geometry::segment_plane(cloud, distance_threshold, ransac_n, num_iterations,
                                                      probability, seed);
        indices_out(seg.inliers, out_indices, capacity, out_n);
        for (int i = 0; i < 4; ++i) out_plane[i] = seg.plane[i];
        return O3D_OK;
    });
}

O3D_API o3d_status o3d_pointcloud_cluster_dbscan(int32_t* out_labels, size_t capacity, size_t* out_n,
                                                 const o3d_pointcloud_t* pc, double eps, int32_t min_points) {
    return guard(__func__, [&]() -> o3d_status {
        const PointCloud& cloud = nonempty_cloud(pc);
        require_finite(eps, "eps");
        check_buffer(cloud.size(), out_labels, capacity, out_n);  // labels are one per point: fail before work
        if (!out_labels) {
            // Size query only; still validate the arguments.
            if (eps <= 0.0) throw o3d::InvalidArgument("eps must be > 0, got " + std::to_string(eps));
            if (min_points < 0) throw o3d::InvalidArgument("min_points must be >= 0, got " + std::to_string(min_points));
            return O3D_OK;
        }
        const std::vector<int32_t> labels = o3d::geometry::cluster_dbscan(cloud, eps, min_points);
        o3d::capi::copy_out(labels.data(), labels.size(), out_labels, capacity, out_n);
        return O3D_OK;
    });
}

O3D_API o3d_status o3d_pointcloud_compute_mean_and_covariance(double out_mean[3], double out_covariance[9],
                                                              const o3d_pointcloud_t* pc) {
    return guard(__func__, [&]() -> o3d_status {
        const PointCloud& cloud = nonempty_cloud(pc);
        require(out_mean, "out_mean");
        require(out_covariance, "out_covariance");
        const auto [mean, cov] = o3d::geometry::compute_mean_and_covariance(cloud);
        for (int i = 0; i < 3; ++i) {
            out_mean[i] = mean[i];
            for (int j = 0; j < 3; ++j) out_covariance[3 * i + j] = cov(i, j);  // row-major
        }
        return O3D_OK;
    });
}

O3D_API o3d_status o3d_pointcloud_compute_mahalanobis_distance(double* out, size_t capacity, size_t* out_n,
                                                               const o3d_pointcloud_t* pc) {
    return guard(__func__, [&]() -> o3d_status {
        const PointCloud& cloud = nonempty_cloud(pc);
        check_buffer(cloud.size(), out, capacity, out_n);
        if (!out) return O3D_OK;
        const std::vector<double> d = o3d::geometry::compute_mahalanobis_distance(cloud);
        o3d::capi::copy_out(d.data(), d.size(), out, capacity, out_n);
        return O3D_OK;
    });
}

}  // extern "C"
