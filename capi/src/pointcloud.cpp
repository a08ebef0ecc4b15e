// SPDX-License-Identifier: MIT
// C API: pointcloud.h over o3d::geometry.
#include <Eigen/Core>
#include <memory>
#include <string>

#include "array_family.h"
#include "internal.h"
#include "o3d/geometry/distances.h"
#include "o3d/geometry/down_sample.h"
#include "o3d/geometry/normals.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/pointcloud.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::PointCloud;
using Vec3List = std::vector<Eigen::Vector3d>;

namespace o3d::capi {

/// @brief The core search parameter for a C one (NULL: KNN 30). Shared with kdtree.cpp.
o3d::kdtree::SearchParam to_search_param(const o3d_search_param_t* param) {
    const o3d_search_param_t defaults{sizeof(o3d_search_param_t), O3D_SEARCH_KNN, 30, 0.0};
    const o3d_search_param_t p = read_options(param, defaults, "param");
    switch (p.kind) {
        case O3D_SEARCH_KNN:
            if (p.knn < 1) throw InvalidArgument("param.knn must be >= 1, got " + std::to_string(p.knn));
            return o3d::kdtree::SearchParam::make_knn(p.knn);
        case O3D_SEARCH_RADIUS:
        case O3D_SEARCH_HYBRID:
            require_finite(p.radius, "param.radius");
            if (p.radius <= 0.0) throw InvalidArgument("param.radius must be > 0, got " + std::to_string(p.radius));
            if (p.kind == O3D_SEARCH_RADIUS) return o3d::kdtree::SearchParam::make_radius(p.radius);
            if (p.knn < 1) throw InvalidArgument("param.knn must be >= 1, got " + std::to_string(p.knn));
            return o3d::kdtree::SearchParam::make_hybrid(p.radius, p.knn);
        default:
            throw InvalidArgument("param.kind " + std::to_string(p.kind) + " is not O3D_SEARCH_KNN/RADIUS/HYBRID");
    }
}

/// @brief Thread count argument: 0 = default, negative is invalid.
int to_num_threads(int32_t num_threads) {
    if (num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(num_threads));
    return num_threads;
}

}  // namespace o3d::capi

namespace {

PointCloud& cloud_of(o3d_pointcloud_t* pc, const char* name = "pc") { return require(pc, name)->cloud; }
const PointCloud& cloud_of(const o3d_pointcloud_t* pc, const char* name = "pc") { return require(pc, name)->cloud; }



/// @brief Hand a new cloud to the caller (`*out` stays NULL if anything before this failed).
o3d_status give(o3d_pointcloud_t** out, PointCloud cloud) {
    auto handle = std::make_unique<o3d_pointcloud>();
    handle->cloud = std::move(cloud);
    *out = handle.release();
    return O3D_OK;
}

o3d_pointcloud_t** require_out(o3d_pointcloud_t** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

/// @brief Copy-out of a per-point result computed only once the caller's buffer is known to fit.
template <typename Compute>
void compute_out(size_t count, double* out, size_t capacity, size_t* out_n, Compute compute) {
    require(out_n, "out_n");
    *out_n = count;
    if (!out) return;
    if (capacity < count)
        throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " values but " + std::to_string(count) +
                                  " are needed");
    const std::vector<double> values = compute();
    o3d::capi::copy_out(values.data(), values.size(), out, capacity, out_n);
}


/// @brief Array `which` (O3D_POINTCLOUD_*) of the cloud. Covariances are symmetric by definition, so
/// their column-major storage is also their row-major layout; set_array rejects asymmetric ones.
o3d::capi::ArraySlot<double> cloud_slot(o3d_pointcloud_t* pc, int32_t which) {
    PointCloud& c = cloud_of(pc);
    switch (which) {
        case O3D_POINTCLOUD_POINTS: return o3d::capi::eigen_slot(c.points, c.has_points());
        case O3D_POINTCLOUD_NORMALS: return o3d::capi::eigen_slot(c.normals, c.has_normals());
        case O3D_POINTCLOUD_COLORS: return o3d::capi::eigen_slot(c.colors, c.has_colors());
        case O3D_POINTCLOUD_COVARIANCES: {
            o3d::capi::ArraySlot<double> s;
            s.data = c.covariances.empty() ? nullptr : c.covariances[0].data();
            s.rows = c.covariances.size();
            s.cols = 9;
            s.present = c.has_covariances();
            s.assign = [&c](const double* src, size_t rows) {
                std::vector<Eigen::Matrix3d> m(rows);
                for (size_t i = 0; i < rows; ++i) {
                    m[i] = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(src + 9 * i);
                    if (!(m[i] - m[i].transpose()).isZero(1e-12 * (1.0 + m[i].cwiseAbs().maxCoeff())))
                        throw o3d::InvalidArgument("covariance " + std::to_string(i) + " is not symmetric");
                }
                c.covariances = std::move(m);
            };
            return s;
        }
        default: o3d::capi::bad_which(which, "an O3D_POINTCLOUD_* array");
    }
}

}  // namespace

extern "C" {

O3D_CAPI_ARRAYS_F64(pointcloud, o3d_pointcloud_t, cloud_slot)
O3D_CAPI_ARRAY_QUERIES(pointcloud, o3d_pointcloud_t, cloud_slot, o3d::capi::no_index_slot)

O3D_API o3d_status o3d_pointcloud_create(o3d_pointcloud_t** out) {
    return guard(__func__, [&] { give(require_out(out), PointCloud{}); });
}

O3D_API void o3d_pointcloud_destroy(o3d_pointcloud_t* pc) { delete pc; }

O3D_API o3d_status o3d_pointcloud_clone(o3d_pointcloud_t** out, const o3d_pointcloud_t* src) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, cloud_of(src, "src"));
    });
}

O3D_API o3d_status o3d_pointcloud_size(size_t* out_n, const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        const PointCloud& c = cloud_of(pc);
        *require(out_n, "out_n") = c.size();
    });
}

O3D_API o3d_status o3d_pointcloud_clear(o3d_pointcloud_t* pc) {
    return guard(__func__, [&] { cloud_of(pc).clear(); });
}


O3D_API o3d_status o3d_pointcloud_append(o3d_pointcloud_t* pc, const o3d_pointcloud_t* other) {
    return guard(__func__, [&] {
        PointCloud& target = cloud_of(pc);
        const PointCloud& source = cloud_of(other, "other");
        if (&target == &source) {
            const PointCloud copy = source;  // `pcd += pcd` must not read what it is growing
            o3d::geometry::append(target, copy);
        } else {
            o3d::geometry::append(target, source);
        }
    });
}

O3D_API o3d_status o3d_pointcloud_transform(o3d_pointcloud_t* pc, const double transform[16]) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        require(transform, "transform");
        o3d::geometry::transform(c, Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(transform));
    });
}

O3D_API o3d_status o3d_pointcloud_translate(o3d_pointcloud_t* pc, const double translation[3], int32_t relative) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        o3d::geometry::translate(c, vec3(translation, "translation"), relative != 0);
    });
}

O3D_API o3d_status o3d_pointcloud_rotate(o3d_pointcloud_t* pc, const double rotation[9], const double center[3]) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        require(rotation, "rotation");
        const Eigen::Vector3d about = center ? vec3(center, "center") : o3d::geometry::center(c);
        o3d::geometry::rotate(c, Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rotation), about);
    });
}

O3D_API o3d_status o3d_pointcloud_scale(o3d_pointcloud_t* pc, double scale, const double center[3]) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        const Eigen::Vector3d about = center ? vec3(center, "center") : o3d::geometry::center(c);
        o3d::geometry::scale(c, scale, about);
    });
}

O3D_API o3d_status o3d_pointcloud_get_min_bound(double out[3], const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        const PointCloud& c = cloud_of(pc);
        write3(out, "out", o3d::geometry::min_bound(c));
    });
}

O3D_API o3d_status o3d_pointcloud_get_max_bound(double out[3], const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        const PointCloud& c = cloud_of(pc);
        write3(out, "out", o3d::geometry::max_bound(c));
    });
}

O3D_API o3d_status o3d_pointcloud_get_center(double out[3], const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        const PointCloud& c = cloud_of(pc);
        write3(out, "out", o3d::geometry::center(c));
    });
}

O3D_API o3d_status o3d_pointcloud_get_axis_aligned_bounding_box(double out_min[3], double out_max[3],
                                                                const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        const PointCloud& c = cloud_of(pc);
        require(out_min, "out_min");
        require(out_max, "out_max");
        write3(out_min, "out_min", o3d::geometry::min_bound(c));
        write3(out_max, "out_max", o3d::geometry::max_bound(c));
    });
}

O3D_API o3d_status o3d_pointcloud_paint_uniform_color(o3d_pointcloud_t* pc, const double rgb[3]) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        o3d::geometry::paint_uniform_color(c, vec3(rgb, "rgb"));
    });
}

O3D_API o3d_status o3d_pointcloud_select_by_index(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                  const int32_t* indices, size_t n, int32_t invert) {
    return guard(__func__, [&] {
        require_out(out);
        const PointCloud& c = cloud_of(pc);
        if (n > 0 && !indices) throw o3d::InvalidArgument("indices is NULL but n = " + std::to_string(n));
        const std::vector<int64_t> list(indices, indices + n);
        give(out, o3d::geometry::select_by_index(c, list, invert != 0));
    });
}

O3D_API o3d_status o3d_pointcloud_remove_non_finite_points(o3d_pointcloud_t* pc, int32_t remove_nan,
                                                           int32_t remove_infinite) {
    return guard(__func__,
                 [&] { o3d::geometry::remove_non_finite_points(cloud_of(pc), remove_nan != 0, remove_infinite != 0); });
}

O3D_API o3d_status o3d_pointcloud_normalize_normals(o3d_pointcloud_t* pc) {
    return guard(__func__, [&] { o3d::geometry::normalize_normals(cloud_of(pc)); });
}

O3D_API o3d_status o3d_pointcloud_voxel_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                    double voxel_size) {
    return guard(__func__, [&] {
        require_out(out);
        const PointCloud& c = cloud_of(pc);
        o3d::capi::require_finite(voxel_size, "voxel_size");
        give(out, o3d::geometry::voxel_down_sample(c, voxel_size));
    });
}

O3D_API o3d_status o3d_pointcloud_uniform_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                      size_t every_k_points) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, o3d::geometry::uniform_down_sample(cloud_of(pc), every_k_points));
    });
}

O3D_API o3d_status o3d_pointcloud_random_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                     double sampling_ratio, uint64_t seed) {
    return guard(__func__, [&] {
        require_out(out);
        const PointCloud& c = cloud_of(pc);
        o3d::capi::require_finite(sampling_ratio, "sampling_ratio");
        give(out, o3d::geometry::random_down_sample(c, sampling_ratio, seed));
    });
}

O3D_API o3d_status o3d_pointcloud_farthest_point_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                             size_t num_samples, size_t start_index) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, o3d::geometry::farthest_point_down_sample(cloud_of(pc), num_samples, start_index));
    });
}

O3D_API o3d_status o3d_search_param_init(o3d_search_param_t* param, uint32_t struct_size) {
    return guard(__func__, [&] {
        const o3d_search_param_t defaults{sizeof(o3d_search_param_t), O3D_SEARCH_KNN, 30, 0.0};
        o3d::capi::init_options(param, struct_size, defaults, "param");
    });
}

O3D_API o3d_status o3d_pointcloud_estimate_normals(o3d_pointcloud_t* pc, const o3d_search_param_t* param,
                                                   int32_t num_threads) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        const auto search = o3d::capi::to_search_param(param);
        o3d::geometry::estimate_normals(c, search, o3d::capi::to_num_threads(num_threads));
    });
}

O3D_API o3d_status o3d_pointcloud_orient_normals_to_align_with_direction(o3d_pointcloud_t* pc,
                                                                        const double direction[3]) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        const Eigen::Vector3d d = direction ? vec3(direction, "direction") : Eigen::Vector3d::UnitZ();
        o3d::geometry::orient_normals_to_align_with_direction(c, d);
    });
}

O3D_API o3d_status o3d_pointcloud_orient_normals_towards_camera_location(o3d_pointcloud_t* pc,
                                                                        const double camera_location[3]) {
    return guard(__func__, [&] {
        PointCloud& c = cloud_of(pc);
        const Eigen::Vector3d cam = camera_location ? vec3(camera_location, "camera_location") : Eigen::Vector3d::Zero();
        o3d::geometry::orient_normals_towards_camera_location(c, cam);
    });
}

O3D_API o3d_status o3d_pointcloud_compute_nearest_neighbor_distance(double* out, size_t capacity, size_t* out_n,
                                                                   const o3d_pointcloud_t* pc, int32_t num_threads) {
    return guard(__func__, [&] {
        const PointCloud& c = cloud_of(pc);
        const int threads = o3d::capi::to_num_threads(num_threads);
        compute_out(c.size(), out, capacity, out_n,
                    [&] { return o3d::geometry::compute_nearest_neighbor_distance(c, threads); });
    });
}

O3D_API o3d_status o3d_pointcloud_compute_point_cloud_distance(double* out, size_t capacity, size_t* out_n,
                                                               const o3d_pointcloud_t* source,
                                                               const o3d_pointcloud_t* target, int32_t num_threads) {
    return guard(__func__, [&] {
        const PointCloud& s = cloud_of(source, "source");
        const PointCloud& t = cloud_of(target, "target");
        const int threads = o3d::capi::to_num_threads(num_threads);
        if (t.points.empty() && !s.points.empty()) throw o3d::InvalidArgument("the target cloud is empty");
        compute_out(s.size(), out, capacity, out_n,
                    [&] { return o3d::geometry::compute_point_cloud_distance(s, t, threads); });
    });
}

}  // extern "C"
