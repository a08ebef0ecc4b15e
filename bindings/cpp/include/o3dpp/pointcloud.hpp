// SPDX-License-Identifier: MIT
#pragma once
/// @file pointcloud.hpp
/// @brief o3dpp::PointCloud (move-only owner of an o3d_pointcloud_t) and SearchParam.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/pointcloud.h"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief Neighbourhood search parameter (KDTreeSearchParamKNN / Radius / Hybrid).
struct SearchParam {
    enum class Kind : int32_t { Knn = O3D_SEARCH_KNN, Radius = O3D_SEARCH_RADIUS, Hybrid = O3D_SEARCH_HYBRID };
    Kind kind = Kind::Knn;
    int knn = 30;
    double radius = 0.0;

    static SearchParam Knn(int k) { return {Kind::Knn, k, 0.0}; }
    static SearchParam Radius(double r) { return {Kind::Radius, 30, r}; }
    static SearchParam Hybrid(double r, int k) { return {Kind::Hybrid, k, r}; }

    /// @brief The C struct (defaults from o3d_search_param_init, then these fields).
    o3d_search_param_t to_c() const {
        o3d_search_param_t c;
        check(o3d_search_param_init(&c, sizeof c));
        c.kind = static_cast<int32_t>(kind);
        c.knn = knn;
        c.radius = radius;
        return c;
    }
};

/// @brief A point cloud: N points, optional N normals and N colors (RGB in [0,1]). Move-only.
class PointCloud {
public:
    /// @brief New empty cloud.
    PointCloud() {
        o3d_pointcloud_t* p = nullptr;
        check(o3d_pointcloud_create(&p));
        h_.reset(p);
    }
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit PointCloud(o3d_pointcloud_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::PointCloud: NULL handle");
    }
    /// @brief Cloud holding `points`.
    explicit PointCloud(const std::vector<Vec3>& points) : PointCloud() { set_points(points); }

    PointCloud(PointCloud&&) noexcept = default;
    PointCloud& operator=(PointCloud&&) noexcept = default;
    PointCloud(const PointCloud&) = delete;
    PointCloud& operator=(const PointCloud&) = delete;

    /// @brief The handle (NULL after a move). Still owned by this object.
    o3d_pointcloud_t* get() const noexcept { return h_.get(); }
    /// @brief Give up ownership: the caller destroys it with o3d_pointcloud_destroy.
    o3d_pointcloud_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Deep copy.
    PointCloud clone() const { return adopt([&](o3d_pointcloud_t** o) { return o3d_pointcloud_clone(o, get()); }); }

    std::size_t size() const {
        size_t n = 0;
        check(o3d_pointcloud_size(&n, get()));
        return n;
    }
    bool empty() const { return size() == 0; }
    bool has_points() const { return flag(&o3d_pointcloud_has_points); }
    bool has_normals() const { return flag(&o3d_pointcloud_has_normals); }
    bool has_colors() const { return flag(&o3d_pointcloud_has_colors); }
    void clear() { check(o3d_pointcloud_clear(get())); }

    // --- setters: copied once; float input is converted in that copy ---
    void set_points(const double* xyz, std::size_t n) { check(o3d_pointcloud_set_array(get(), O3D_POINTCLOUD_POINTS, xyz, n)); }
    void set_points(const float* xyz, std::size_t n) { check(o3d_pointcloud_set_array_f32(get(), O3D_POINTCLOUD_POINTS, xyz, n)); }
    void set_points(const std::vector<Vec3>& v) { set_points(flat(v), v.size()); }
    void set_points(const std::vector<std::array<float, 3>>& v) { set_points(flat(v), v.size()); }
    void set_normals(const double* xyz, std::size_t n) { check(o3d_pointcloud_set_array(get(), O3D_POINTCLOUD_NORMALS, xyz, n)); }
    void set_normals(const float* xyz, std::size_t n) { check(o3d_pointcloud_set_array_f32(get(), O3D_POINTCLOUD_NORMALS, xyz, n)); }
    void set_normals(const std::vector<Vec3>& v) { set_normals(flat(v), v.size()); }
    void set_normals(const std::vector<std::array<float, 3>>& v) { set_normals(flat(v), v.size()); }
    void set_colors(const double* rgb, std::size_t n) { check(o3d_pointcloud_set_array(get(), O3D_POINTCLOUD_COLORS, rgb, n)); }
    void set_colors(const float* rgb, std::size_t n) { check(o3d_pointcloud_set_array_f32(get(), O3D_POINTCLOUD_COLORS, rgb, n)); }
    void set_colors(const std::vector<Vec3>& v) { set_colors(flat(v), v.size()); }
    void set_colors(const std::vector<std::array<float, 3>>& v) { set_colors(flat(v), v.size()); }

    // --- copies ---
    std::vector<Vec3> get_points() const { return copy(&o3d_pointcloud_get_points); }
    std::vector<Vec3> get_normals() const { return copy(&o3d_pointcloud_get_normals); }
    std::vector<Vec3> get_colors() const { return copy(&o3d_pointcloud_get_colors); }

    // --- borrowed views: valid until the next mutating call or destruction ---
    Rows3<const double> points() const { return view(&o3d_pointcloud_points_view); }
    Rows3<const double> normals() const { return view(&o3d_pointcloud_normals_view); }
    Rows3<const double> colors() const { return view(&o3d_pointcloud_colors_view); }
    Rows3<double> points_mutable() { return mutable_view(&o3d_pointcloud_points_mutable_view); }
    Rows3<double> normals_mutable() { return mutable_view(&o3d_pointcloud_normals_mutable_view); }
    Rows3<double> colors_mutable() { return mutable_view(&o3d_pointcloud_colors_mutable_view); }

    /// @brief Concatenate `other` (Open3D `pcd += other`).
    PointCloud& operator+=(const PointCloud& other) {
        check(o3d_pointcloud_append(get(), other.get()));
        return *this;
    }
    PointCloud& append(const PointCloud& other) { return *this += other; }

    PointCloud& transform(const Mat4& t) {
        check(o3d_pointcloud_transform(get(), t.data()));
        return *this;
    }
    PointCloud& translate(const Vec3& t, bool relative = true) {
        check(o3d_pointcloud_translate(get(), t.data(), relative ? 1 : 0));
        return *this;
    }
    /// @brief Rotate about the cloud's center.
    PointCloud& rotate(const Mat3& r) {
        check(o3d_pointcloud_rotate(get(), r.data(), nullptr));
        return *this;
    }
    PointCloud& rotate(const Mat3& r, const Vec3& center) {
        check(o3d_pointcloud_rotate(get(), r.data(), center.data()));
        return *this;
    }
    /// @brief Scale about the cloud's center.
    PointCloud& scale(double s) {
        check(o3d_pointcloud_scale(get(), s, nullptr));
        return *this;
    }
    PointCloud& scale(double s, const Vec3& center) {
        check(o3d_pointcloud_scale(get(), s, center.data()));
        return *this;
    }

    Vec3 get_min_bound() const { return vec3(&o3d_pointcloud_get_min_bound); }
    Vec3 get_max_bound() const { return vec3(&o3d_pointcloud_get_max_bound); }
    Vec3 get_center() const { return vec3(&o3d_pointcloud_get_center); }
    /// @brief {min corner, max corner}.
    std::array<Vec3, 2> get_axis_aligned_bounding_box() const {
        std::array<Vec3, 2> box{};
        check(o3d_pointcloud_get_axis_aligned_bounding_box(box[0].data(), box[1].data(), get()));
        return box;
    }
    PointCloud& paint_uniform_color(const Vec3& rgb) {
        check(o3d_pointcloud_paint_uniform_color(get(), rgb.data()));
        return *this;
    }
    PointCloud select_by_index(const std::vector<int32_t>& indices, bool invert = false) const {
        return adopt([&](o3d_pointcloud_t** o) {
            return o3d_pointcloud_select_by_index(o, get(), indices.data(), indices.size(), invert ? 1 : 0);
        });
    }
    PointCloud& remove_non_finite_points(bool remove_nan = true, bool remove_infinite = true) {
        check(o3d_pointcloud_remove_non_finite_points(get(), remove_nan ? 1 : 0, remove_infinite ? 1 : 0));
        return *this;
    }
    PointCloud& normalize_normals() {
        check(o3d_pointcloud_normalize_normals(get()));
        return *this;
    }

    PointCloud voxel_down_sample(double voxel_size) const {
        return adopt([&](o3d_pointcloud_t** o) { return o3d_pointcloud_voxel_down_sample(o, get(), voxel_size); });
    }
    PointCloud uniform_down_sample(std::size_t every_k_points) const {
        return adopt([&](o3d_pointcloud_t** o) { return o3d_pointcloud_uniform_down_sample(o, get(), every_k_points); });
    }
    PointCloud random_down_sample(double sampling_ratio, uint64_t seed = 0) const {
        return adopt(
            [&](o3d_pointcloud_t** o) { return o3d_pointcloud_random_down_sample(o, get(), sampling_ratio, seed); });
    }
    PointCloud farthest_point_down_sample(std::size_t num_samples, std::size_t start_index = 0) const {
        return adopt([&](o3d_pointcloud_t** o) {
            return o3d_pointcloud_farthest_point_down_sample(o, get(), num_samples, start_index);
        });
    }

    /// @brief PCA normals (default KNN 30). num_threads 0 = library default.
    PointCloud& estimate_normals(const SearchParam& param = SearchParam{}, int num_threads = 0) {
        const o3d_search_param_t c = param.to_c();
        check(o3d_pointcloud_estimate_normals(get(), &c, num_threads));
        return *this;
    }
    PointCloud& orient_normals_to_align_with_direction(const Vec3& direction = {0, 0, 1}) {
        check(o3d_pointcloud_orient_normals_to_align_with_direction(get(), direction.data()));
        return *this;
    }
    PointCloud& orient_normals_towards_camera_location(const Vec3& camera_location = {0, 0, 0}) {
        check(o3d_pointcloud_orient_normals_towards_camera_location(get(), camera_location.data()));
        return *this;
    }
    std::vector<double> compute_nearest_neighbor_distance(int num_threads = 0) const {
        size_t n = 0;
        check(o3d_pointcloud_compute_nearest_neighbor_distance(nullptr, 0, &n, get(), num_threads));
        std::vector<double> out(n);
        check(o3d_pointcloud_compute_nearest_neighbor_distance(out.data(), out.size(), &n, get(), num_threads));
        out.resize(n);
        return out;
    }
    /// @brief For each point of this cloud, the distance to the closest point of `target`.
    std::vector<double> compute_point_cloud_distance(const PointCloud& target, int num_threads = 0) const {
        size_t n = 0;
        check(o3d_pointcloud_compute_point_cloud_distance(nullptr, 0, &n, get(), target.get(), num_threads));
        std::vector<double> out(n);
        check(o3d_pointcloud_compute_point_cloud_distance(out.data(), out.size(), &n, get(), target.get(), num_threads));
        out.resize(n);
        return out;
    }

    // --- tools: filters, segmentation, statistics ---

    /// @brief Drop points whose mean distance to their `nb_neighbors` nearest points is above the
    /// cloud's mean of that distance + `std_ratio` standard deviations. {kept cloud, kept indices (ascending)}.
    std::pair<PointCloud, std::vector<int32_t>> remove_statistical_outlier(int nb_neighbors, double std_ratio) const {
        return filtered([&](o3d_pointcloud_t** o, int32_t* idx, size_t cap, size_t* n) {
            return o3d_pointcloud_remove_statistical_outlier(o, idx, cap, n, get(), nb_neighbors, std_ratio);
        });
    }
    /// @brief Keep points with at least `nb_points` other points within `radius`.
    /// {kept cloud, kept indices (ascending)}.
    std::pair<PointCloud, std::vector<int32_t>> remove_radius_outlier(int nb_points, double radius) const {
        return filtered([&](o3d_pointcloud_t** o, int32_t* idx, size_t cap, size_t* n) {
            return o3d_pointcloud_remove_radius_outlier(o, idx, cap, n, get(), nb_points, radius);
        });
    }
    /// @brief Points inside the box [min_bound, max_bound], bounds included (outside when `invert`).
    PointCloud crop_aabb(const Vec3& min_bound, const Vec3& max_bound, bool invert = false) const {
        return adopt([&](o3d_pointcloud_t** o) {
            return o3d_pointcloud_crop_aabb(o, get(), min_bound.data(), max_bound.data(), invert ? 1 : 0);
        });
    }
    /// @brief Points inside `obb`, boundary included (outside when `invert`).
    PointCloud crop(const OrientedBoundingBox& obb, bool invert = false) const {
        const o3d_obb_t c = obb.to_c();
        return adopt([&](o3d_pointcloud_t** o) { return o3d_pointcloud_crop_obb(o, get(), &c, invert ? 1 : 0); });
    }
    /// @brief Oriented box of the points (see OrientedBoundingBox::create_from_points).
    OrientedBoundingBox get_oriented_bounding_box(bool robust = false) const {
        o3d_obb_t c{};
        check(o3d_pointcloud_get_oriented_bounding_box(&c, get(), robust ? 1 : 0));
        return OrientedBoundingBox::from_c(c);
    }
    /// @brief RANSAC plane: {(a, b, c, d) with a x + b y + c z + d = 0 and unit (a, b, c), inlier indices
    /// (ascending)}. Same seed → same result on any thread count.
    std::pair<std::array<double, 4>, std::vector<int32_t>> segment_plane(double distance_threshold, int ransac_n = 3,
                                                                         int num_iterations = 100,
                                                                         double probability = 0.99999999,
                                                                         uint64_t seed = 0) const {
        std::pair<std::array<double, 4>, std::vector<int32_t>> out{};
        out.second = indices([&](int32_t* idx, size_t cap, size_t* n) {
            return o3d_pointcloud_segment_plane(out.first.data(), idx, cap, n, get(), distance_threshold, ransac_n,
                                                num_iterations, probability, seed);
        });
        return out;
    }
    /// @brief DBSCAN labels, one per point: clusters 0, 1, ... in order of their lowest point index, -1 noise.
    std::vector<int32_t> cluster_dbscan(double eps, int min_points) const {
        return indices([&](int32_t* labels, size_t cap, size_t* n) {
            return o3d_pointcloud_cluster_dbscan(labels, cap, n, get(), eps, min_points);
        });
    }
    /// @brief {mean, row-major covariance divided by N}. Empty cloud → Error.
    std::pair<Vec3, Mat3> compute_mean_and_covariance() const {
        std::pair<Vec3, Mat3> out{};
        check(o3d_pointcloud_compute_mean_and_covariance(out.first.data(), out.second.data(), get()));
        return out;
    }
    /// @brief Mahalanobis distance of each point to the cloud's distribution.
    std::vector<double> compute_mahalanobis_distance() const {
        std::vector<double> out(size());
        size_t n = 0;
        check(o3d_pointcloud_compute_mahalanobis_distance(out.data(), out.size(), &n, get()));
        out.resize(n);
        return out;
    }

    // --- per-point covariances (row-major 3x3 each); they follow selection, append and transforms ---

    /// @brief True when there is one covariance per point.
    bool has_covariances() const { return flag(&o3d_pointcloud_has_covariances); }
    void set_covariances(const double* data, std::size_t n) { check(o3d_pointcloud_set_array(get(), O3D_POINTCLOUD_COVARIANCES, data, n)); }
    void set_covariances(const std::vector<Mat3>& c) {
        set_covariances(c.empty() ? nullptr : c.front().data(), c.size());
    }
    std::vector<Mat3> get_covariances() const {
        static_assert(sizeof(Mat3) == 9 * sizeof(double), "Mat3 must be 9 packed doubles");
        size_t n = 0;
        check(o3d_pointcloud_get_array(nullptr, 0, &n, get(), O3D_POINTCLOUD_COVARIANCES));
        std::vector<Mat3> out(n);
        check(o3d_pointcloud_get_array(n ? out.front().data() : nullptr, n, &n, get(), O3D_POINTCLOUD_COVARIANCES));
        out.resize(n);
        return out;
    }
    /// @brief Borrowed covariances as 9 * count values (valid until the next mutation).
    Span<const double> covariances() const {
        const double* data = nullptr;
        size_t n = 0;
        check(o3d_pointcloud_array_view(&data, &n, get(), O3D_POINTCLOUD_COVARIANCES));
        return {data, 9 * n};
    }
    /// @brief Covariance of each point's neighbourhood (default KNN 30, as Open3D).
    PointCloud& estimate_covariances(const SearchParam& param = SearchParam{}) {
        const o3d_search_param_t c = param.to_c();
        check(o3d_pointcloud_estimate_covariances(get(), &c));
        return *this;
    }

    /// @brief Run `create(o3d_pointcloud_t**)` and own what it returns.
    template <typename F>
    static PointCloud adopt(F&& create) {
        o3d_pointcloud_t* p = nullptr;
        check(create(&p));
        return PointCloud(p);
    }

private:
    /// @brief Run `fn(int32_t* buffer, capacity, out_n)` with room for one index per point.
    template <typename F>
    std::vector<int32_t> indices(F&& fn) const {
        std::vector<int32_t> out(size());
        size_t n = 0;
        check(fn(out.data(), out.size(), &n));
        out.resize(n < out.size() ? n : out.size());
        return out;
    }
    /// @brief Run a filter writing a new cloud and its kept indices.
    template <typename F>
    std::pair<PointCloud, std::vector<int32_t>> filtered(F&& fn) const {
        o3d_pointcloud_t* p = nullptr;
        std::vector<int32_t> kept = indices([&](int32_t* idx, size_t cap, size_t* n) { return fn(&p, idx, cap, n); });
        return {PointCloud(p), std::move(kept)};
    }
    template <typename T>
    static const T* flat(const std::vector<std::array<T, 3>>& v) {
        static_assert(sizeof(std::array<T, 3>) == 3 * sizeof(T), "std::array<T,3> must be 3 packed values");
        return v.empty() ? nullptr : v.front().data();
    }
    bool flag(o3d_status (*fn)(const o3d_pointcloud_t*, int32_t*)) const {
        int32_t out = 0;
        check(fn(get(), &out));
        return out != 0;
    }
    Vec3 vec3(o3d_status (*fn)(const o3d_pointcloud_t*, double*)) const {
        Vec3 out{};
        check(fn(get(), out.data()));
        return out;
    }
    std::vector<Vec3> copy(o3d_status (*fn)(const o3d_pointcloud_t*, double*, size_t, size_t*)) const {
        size_t n = 0;
        check(fn(get(), nullptr, 0, &n));
        std::vector<Vec3> out(n);
        check(fn(get(), n ? out.front().data() : nullptr, n, &n));
        out.resize(n);
        return out;
    }
    Rows3<const double> view(o3d_status (*fn)(const o3d_pointcloud_t*, const double**, size_t*)) const {
        const double* data = nullptr;
        size_t n = 0;
        check(fn(get(), &data, &n));
        return {data, n};
    }
    Rows3<double> mutable_view(o3d_status (*fn)(o3d_pointcloud_t*, double**, size_t*)) {
        double* data = nullptr;
        size_t n = 0;
        check(fn(get(), &data, &n));
        return {data, n};
    }

    UniqueHandle<o3d_pointcloud_t, &o3d_pointcloud_destroy> h_;
};

}  // namespace o3dpp
