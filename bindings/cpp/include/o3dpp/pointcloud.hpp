// SPDX-License-Identifier: MIT
#pragma once
/// @file pointcloud.hpp
/// @brief o3dpp::PointCloud (move-only owner of an o3d_pointcloud_t) and SearchParam.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/pointcloud.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/generated/pointcloud.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/indexlists.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief Neighbourhood search parameter (KDTreeSearchParamKNN / Radius / Hybrid); defaults from
/// o3d_search_param_init.
struct SearchParam : detail::SearchParamBase {
    using Kind = SearchKind;
    SearchParam() = default;
    /// @brief The search a field of an option struct holds (e.g. PlanarPatchOptions::search_param).
    SearchParam(const detail::SearchParamBase& base) : detail::SearchParamBase(base) {}  // NOLINT: implicit
    SearchParam(Kind k, int max_nn, double r) {
        kind = k;
        knn = max_nn;
        radius = r;
    }
    static SearchParam Knn(int k) { return {Kind::Knn, k, SearchParam().radius}; }
    static SearchParam Radius(double r) { return {Kind::Radius, SearchParam().knn, r}; }
    static SearchParam Hybrid(double r, int k) { return {Kind::Hybrid, k, r}; }
};

namespace detail {
using PointCloudArrayFns =
    ArrayFns<&o3d_pointcloud_has_array, &o3d_pointcloud_array_shape, &o3d_pointcloud_get_array,
             &o3d_pointcloud_array_view, &o3d_pointcloud_array_mutable_view, &o3d_pointcloud_set_array,
             &o3d_pointcloud_set_array_f32>;
}  // namespace detail

/// @brief What PointCloud::voxel_down_sample_and_trace returns (Open3D's tuple).
struct VoxelDownSampleTrace;

/// @brief A point cloud: N points, optional N normals, N colors (RGB in [0,1]) and N covariances. Move-only.
/// The methods that pass their arguments to one C function are generated (detail::PointCloudCalls).
class PointCloud : public Owner<PointCloud, o3d_pointcloud_t, &o3d_pointcloud_destroy>,
                   public Arrays<PointCloud, PointCloudArray, detail::PointCloudArrayFns>,
                   public detail::PointCloudCalls<PointCloud> {
    friend class detail::PointCloudCalls<PointCloud>;  // checks its calls with done
    using A = PointCloudArray;

public:
    /// @brief New empty cloud.
    PointCloud() : Owner(make(&o3d_pointcloud_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit PointCloud(o3d_pointcloud_t* owned) : Owner(owned) {}
    /// @brief Cloud holding `points`.
    explicit PointCloud(const std::vector<Vec3>& points) : PointCloud() { set_points(points); }

    /// @brief Deep copy.
    PointCloud clone() const { return derive(&o3d_pointcloud_clone); }

    bool empty() const { return size() == 0; }

    // --- named arrays (see Arrays for the generic accessor): setters copy once, float converted in that copy;
    // views are borrowed until the next mutating call or destruction ---
    bool has_points() const { return has_array(A::Points); }
    bool has_normals() const { return has_array(A::Normals); }
    bool has_colors() const { return has_array(A::Colors); }
    template <typename Row = Vec3>
    void set_points(const std::vector<Row>& v) { set_array(A::Points, v); }
    template <typename T>
    void set_points(const T* xyz, std::size_t n) { set_array(A::Points, xyz, n); }
    template <typename Row = Vec3>
    void set_normals(const std::vector<Row>& v) { set_array(A::Normals, v); }
    template <typename T>
    void set_normals(const T* xyz, std::size_t n) { set_array(A::Normals, xyz, n); }
    template <typename Row = Vec3>
    void set_colors(const std::vector<Row>& v) { set_array(A::Colors, v); }
    template <typename T>
    void set_colors(const T* rgb, std::size_t n) { set_array(A::Colors, rgb, n); }
    std::vector<Vec3> get_points() const { return get_array(A::Points); }
    std::vector<Vec3> get_normals() const { return get_array(A::Normals); }
    std::vector<Vec3> get_colors() const { return get_array(A::Colors); }
    Rows3<const double> points() const { return array(A::Points); }
    Rows3<const double> normals() const { return array(A::Normals); }
    Rows3<const double> colors() const { return array(A::Colors); }
    Rows3<double> points_mutable() { return array_mutable(A::Points); }
    Rows3<double> normals_mutable() { return array_mutable(A::Normals); }
    Rows3<double> colors_mutable() { return array_mutable(A::Colors); }

    /// @brief Concatenate `other` (Open3D `pcd += other`).
    PointCloud& operator+=(const PointCloud& other) { return append(other); }
    /// @brief {min corner, max corner}.
    std::array<Vec3, 2> get_axis_aligned_bounding_box() const {
        std::array<Vec3, 2> box{};
        check(o3d_pointcloud_get_axis_aligned_bounding_box(box[0].data(), box[1].data(), get()));
        return box;
    }

    PointCloud select_by_index(const std::vector<int32_t>& indices, bool invert = false) const {
        return derive(&o3d_pointcloud_select_by_index, indices.data(), indices.size(), invert ? 1 : 0);
    }

    /// @brief PCA normals (default: the library's search parameter). num_threads 0 = library default.
    PointCloud& estimate_normals(const SearchParam& param = SearchParam{}, int num_threads = 0) {
        const o3d_search_param_t c = param.to_c();
        return done(o3d_pointcloud_estimate_normals(get(), &c, num_threads));
    }
    std::vector<double> compute_nearest_neighbor_distance(int num_threads = 0) const {
        return copy_out<double>(&o3d_pointcloud_compute_nearest_neighbor_distance, num_threads);
    }
    /// @brief For each point of this cloud, the distance to the closest point of `target`.
    std::vector<double> compute_point_cloud_distance(const PointCloud& target, int num_threads = 0) const {
        return copy_out<double>(&o3d_pointcloud_compute_point_cloud_distance, target.get(), num_threads);
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
    /// @brief Intrinsic Shape Signature keypoints (Zhong 2009): {keypoints with their normals and colors, their
    /// indices in this cloud (ascending)}. @see o3d.geometry.keypoint.compute_iss_keypoints
    std::pair<PointCloud, std::vector<int32_t>> compute_iss_keypoints(const IssOptions& options = {}) const {
        const o3d_iss_options_t c = options.to_c();
        return filtered([&](o3d_pointcloud_t** o, int32_t* idx, size_t cap, size_t* n) {
            return o3d_pointcloud_compute_iss_keypoints(o, idx, cap, n, get(), &c);
        });
    }
    /// @brief Points inside `obb`, boundary included (outside when `invert`).
    PointCloud crop(const OrientedBoundingBox& obb, bool invert = false) const {
        const o3d_obb_t c = obb.to_c();
        return derive(&o3d_pointcloud_crop_obb, &c, invert ? 1 : 0);
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
        return copy_out<double>(&o3d_pointcloud_compute_mahalanobis_distance);
    }

    // --- per-point covariances (row-major 3x3 each); they follow selection, append and transforms ---

    /// @brief True when there is one covariance per point.
    bool has_covariances() const { return has_array(A::Covariances); }
    void set_covariances(const double* data, std::size_t n) { set_array(A::Covariances, data, n); }
    void set_covariances(const std::vector<Mat3>& c) { set_array(A::Covariances, c); }
    std::vector<Mat3> get_covariances() const { return get_array<Mat3>(A::Covariances); }
    /// @brief Borrowed covariances as 9 * count values (valid until the next mutation).
    Span<const double> covariances() const { return array(A::Covariances).flat(); }
    /// @brief Covariance of each point's neighbourhood (default: the library's search parameter).
    PointCloud& estimate_covariances(const SearchParam& param = SearchParam{}) {
        const o3d_search_param_t c = param.to_c();
        return done(o3d_pointcloud_estimate_covariances(get(), &c));
    }

    /// @brief Each point's neighbourhood covariance (divided by the count, the point itself included; fewer than 3
    /// neighbours give the identity), without changing `input` (Open3D's static estimate_point_covariances).
    static std::vector<Mat3> estimate_point_covariances(const PointCloud& input,
                                                        const SearchParam& param = SearchParam{}, int num_threads = 0) {
        const o3d_search_param_t c = param.to_c();
        return input.copy_out<Mat3>(&o3d_pointcloud_estimate_point_covariances, &c, num_threads);
    }

    // --- smoothing (Open3D 0.20); smooth_laplacian and smooth_taubin are generated ---

    /// @brief Moving-least-squares smoothing: each point projected onto the weighted PCA plane of its neighbourhood
    /// (Open3D's default search: hybrid, radius 0.05, 30 neighbours).
    PointCloud smooth_mls(const SearchParam& param = SearchParam::Hybrid(0.05, 30)) const {
        const o3d_search_param_t c = param.to_c();
        return derive(&o3d_pointcloud_smooth_mls, &c);
    }
    /// @brief Bilateral smoothing (one pass): neighbours weighted by distance (`sigma_s`) and by offset along the
    /// point's normal (`sigma_r`).
    PointCloud smooth_bilateral(const SearchParam& param = SearchParam::Hybrid(0.05, 30), double sigma_s = 0.05,
                                double sigma_r = 0.05) const {
        const o3d_search_param_t c = param.to_c();
        return derive(&o3d_pointcloud_smooth_bilateral, &c, sigma_s, sigma_r);
    }

    // --- bounding volumes, planar patches, traced down-sampling ---

    /// @brief The minimum-volume oriented box of the points (see OrientedBoundingBox::create_from_points_minimal).
    OrientedBoundingBox get_minimal_oriented_bounding_box(bool robust = false) const {
        o3d_obb_t c{};
        check(o3d_pointcloud_get_minimal_oriented_bounding_box(&c, get(), robust ? 1 : 0));
        return OrientedBoundingBox::from_c(c);
    }
    /// @brief The minimum-volume enclosing ellipsoid (see OrientedBoundingEllipsoid::create_from_points).
    OrientedBoundingEllipsoid get_oriented_bounding_ellipsoid(bool robust = false) const {
        o3d_obe_t c{};
        check(o3d_pointcloud_get_oriented_bounding_ellipsoid(&c, get(), robust ? 1 : 0));
        return OrientedBoundingEllipsoid::from_c(c);
    }
    /// @brief Planar patches (Araujo & Oliveira 2020): one oriented box per patch (column 2 of R its normal),
    /// largest first. The cloud needs normals.
    std::vector<OrientedBoundingBox> detect_planar_patches(const PlanarPatchOptions& options = {}) const {
        const o3d_planar_patch_options_t c = options.to_c();
        using Box = std::array<double, 15>;  // o3d_obb_t's fields in order
        const std::vector<Box> rows = copy_out<Box>(&o3d_pointcloud_detect_planar_patches, &c);
        std::vector<OrientedBoundingBox> out;
        out.reserve(rows.size());
        for (const Box& r : rows) {
            OrientedBoundingBox b;
            std::copy(r.begin(), r.begin() + 3, b.center.begin());
            std::copy(r.begin() + 3, r.begin() + 12, b.R.begin());
            std::copy(r.begin() + 12, r.end(), b.extent.begin());
            out.push_back(b);
        }
        return out;
    }
    /// @brief Voxel down-sampling that remembers where each output point came from (Open3D's
    /// voxel_down_sample_and_trace): see VoxelDownSampleTrace.
    VoxelDownSampleTrace voxel_down_sample_and_trace(double voxel_size, const Vec3& min_bound, const Vec3& max_bound,
                                                     bool approximate_class = false) const;

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
};

struct VoxelDownSampleTrace {
    PointCloud cloud;  ///< one mean point per occupied voxel, sorted by voxel (z, y, x)
    /// @brief Per output point, per octant of its voxel (bit 0, 1, 2: upper half along x, y, z), the largest input
    /// index in that octant, or -1.
    std::vector<std::array<int, 8>> cubic_ids;
    IndexLists original_indices;  ///< per output point, the input indices it averages (ascending)
};

inline VoxelDownSampleTrace PointCloud::voxel_down_sample_and_trace(double voxel_size, const Vec3& min_bound,
                                                                    const Vec3& max_bound,
                                                                    bool approximate_class) const {
    o3d_pointcloud_t* cloud = nullptr;
    o3d_index_lists_t* cubic = nullptr;
    o3d_index_lists_t* original = nullptr;
    const o3d_status status = o3d_pointcloud_voxel_down_sample_and_trace(
        &cloud, &cubic, &original, get(), voxel_size, min_bound.data(), max_bound.data(), approximate_class ? 1 : 0);
    UniqueHandle<o3d_pointcloud_t, &o3d_pointcloud_destroy> owned(cloud);
    UniqueHandle<o3d_index_lists_t, &o3d_index_lists_destroy> owned_cubic(cubic), owned_original(original);
    check(status);
    const IndexLists cubic_lists = detail::take_index_lists(owned_cubic.release());
    VoxelDownSampleTrace out{PointCloud(owned.release()), {}, detail::take_index_lists(owned_original.release())};
    out.cubic_ids.reserve(cubic_lists.size());
    for (const std::vector<int>& ids : cubic_lists) {
        if (ids.size() != 8) throw Error(O3D_ERROR_INTERNAL, "o3dpp: a cubic-id list without 8 entries");
        std::array<int, 8> row{};
        std::copy(ids.begin(), ids.end(), row.begin());
        out.cubic_ids.push_back(row);
    }
    return out;
}

}  // namespace o3dpp
