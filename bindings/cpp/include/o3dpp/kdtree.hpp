// SPDX-License-Identifier: MIT
#pragma once
/// @file kdtree.hpp
/// @brief o3dpp::KDTreeFlann (over 3-D points or points of any dimension, e.g. a Feature) and
/// o3dpp::SearchResult (flat batch search results).
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "o3d/feature.h"
#include "o3d/kdtree.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/feature.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief Result of a batch search: for query i, neighbours offsets()[i] .. offsets()[i+1]-1,
/// sorted by increasing distance. Move-only; independent of the tree it came from.
class SearchResult : public Owner<SearchResult, o3d_search_result_t, &o3d_search_result_destroy> {
public:
    explicit SearchResult(o3d_search_result_t* owned) : Owner(owned) {}

    std::size_t num_queries() const { return counts()[0]; }
    /// @brief Neighbours over all queries.
    std::size_t total() const { return counts()[1]; }

    // Borrowed views, valid while this SearchResult lives.
    Span<const int64_t> offsets() const { return {view().offsets, num_queries() + 1}; }
    Span<const int32_t> indices() const { return {view().indices, total()}; }
    Span<const double> distances2() const { return {view().distances2, total()}; }
    /// @brief Neighbour indices of query `i`.
    Span<const int32_t> indices(std::size_t i) const { return of_query(i, view().indices); }
    /// @brief Squared neighbour distances of query `i`.
    Span<const double> distances2(std::size_t i) const { return of_query(i, view().distances2); }

    // Copies.
    std::vector<int64_t> get_offsets() const { return copy_out<int64_t>(&o3d_search_result_get_offsets); }
    std::vector<int32_t> get_indices() const { return copy_out<int32_t>(&o3d_search_result_get_indices); }
    std::vector<double> get_distances2() const { return copy_out<double>(&o3d_search_result_get_distances2); }

private:
    struct View {
        const int64_t* offsets = nullptr;
        const int32_t* indices = nullptr;
        const double* distances2 = nullptr;
    };
    std::array<std::size_t, 2> counts() const {
        std::array<std::size_t, 2> c{};
        check(o3d_search_result_counts(&c[0], &c[1], get()));
        return c;
    }
    View view() const {
        View v;
        check(o3d_search_result_view(&v.offsets, &v.indices, &v.distances2, get()));
        return v;
    }
    /// @brief The part of `values` (indices or distances) that belongs to query `i`.
    template <typename T>
    Span<const T> of_query(std::size_t i, const T* values) const {
        if (i >= num_queries())
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::SearchResult: query index out of range");
        const int64_t* offsets = view().offsets;
        return {values + offsets[i], static_cast<std::size_t>(offsets[i + 1] - offsets[i])};
    }
};

/// @brief KD-tree over 3-D points, or over points of any dimension (a Feature, from_points_xd).
/// Copies them: independent of its source. Move-only.
class KDTreeFlann : public Owner<KDTreeFlann, o3d_kdtree_t, &o3d_kdtree_destroy> {
public:
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit KDTreeFlann(o3d_kdtree_t* owned) : Owner(owned) {}
    explicit KDTreeFlann(const PointCloud& cloud)
        : Owner(make([&](o3d_kdtree_t** o) { return o3d_kdtree_create_from_pointcloud(o, cloud.get()); })) {}
    KDTreeFlann(const double* xyz, std::size_t n)
        : Owner(make([&](o3d_kdtree_t** o) { return o3d_kdtree_create_from_points(o, xyz, n); })) {}
    explicit KDTreeFlann(const std::vector<Vec3>& points)
        : KDTreeFlann(points.empty() ? nullptr : points.front().data(), points.size()) {}
    /// @brief Over the descriptors of `feature` (copied). @see o3d.geometry.KDTreeFlann(feature)
    explicit KDTreeFlann(const Feature& feature)
        : Owner(make([&](o3d_kdtree_t** o) { return o3d_kdtree_create_from_feature(o, feature.get()); })) {}
    /// @brief Over `n` points of `dimension` doubles each, one after the other (copied).
    static KDTreeFlann from_points_xd(const double* data, std::size_t dimension, std::size_t n) {
        return create(&o3d_kdtree_create_from_points_xd, data, dimension, n);
    }
    /// @brief As above from `data.size() / dimension` points (the size must be a multiple of it).
    static KDTreeFlann from_points_xd(const std::vector<double>& data, std::size_t dimension) {
        return from_points_xd(data.data(), dimension, rows_of(data.size(), dimension));
    }

    std::size_t size() const { return query(&o3d_kdtree_size); }
    /// @brief Dimension of the indexed points (3 for trees over clouds).
    std::size_t dimension() const { return query(&o3d_kdtree_dimension); }

    /// @brief Batch search of `num_queries` rows of `queries` (double or float). num_threads 0 = library default.
    template <typename T>
    SearchResult search(const T* queries, std::size_t num_queries, const SearchParam& param,
                        int num_threads = 0) const {
        return run(param, [&](o3d_search_result_t** o, const o3d_search_param_t* c) {
            if constexpr (std::is_same_v<T, float>)
                return o3d_kdtree_search_f32(o, get(), queries, num_queries, c, num_threads);
            else
                return o3d_kdtree_search(o, get(), queries, num_queries, c, num_threads);
        });
    }
    SearchResult search(const std::vector<Vec3>& queries, const SearchParam& param, int num_threads = 0) const {
        return search(queries.empty() ? nullptr : queries.front().data(), queries.size(), param, num_threads);
    }
    SearchResult search_knn(const std::vector<Vec3>& queries, int knn, int num_threads = 0) const {
        return search(queries, SearchParam::Knn(knn), num_threads);
    }
    SearchResult search_radius(const std::vector<Vec3>& queries, double radius, int num_threads = 0) const {
        return search(queries, SearchParam::Radius(radius), num_threads);
    }
    SearchResult search_hybrid(const std::vector<Vec3>& queries, double radius, int max_nn,
                               int num_threads = 0) const {
        return search(queries, SearchParam::Hybrid(radius, max_nn), num_threads);
    }

    /// @brief Batch search of `num_queries` rows of `dimension` doubles (the tree's dimension).
    /// @see KDTreeFlann.search_knn_vector_xd
    SearchResult search_xd(const double* queries, std::size_t num_queries, std::size_t dimension,
                           const SearchParam& param, int num_threads = 0) const {
        return run(param, [&](o3d_search_result_t** o, const o3d_search_param_t* c) {
            return o3d_kdtree_search_xd(o, get(), queries, num_queries, dimension, c, num_threads);
        });
    }
    /// @brief As above with `queries.size() / dimension` rows.
    SearchResult search_xd(const std::vector<double>& queries, std::size_t dimension, const SearchParam& param,
                           int num_threads = 0) const {
        return search_xd(queries.data(), rows_of(queries.size(), dimension), dimension, param, num_threads);
    }
    /// @brief Every descriptor of `feature` as a query.
    SearchResult search_xd(const Feature& feature, const SearchParam& param, int num_threads = 0) const {
        const Span<const double> d = feature.data();
        return search_xd(d.data(), feature.num(), feature.dimension(), param, num_threads);
    }
    /// @brief The `knn` nearest points of one query of any dimension (Open3D search_knn_vector_xd).
    SearchResult search_knn_vector_xd(const std::vector<double>& query, int knn) const {
        return search_xd(query.data(), 1, query.size(), SearchParam::Knn(knn));
    }
    /// @brief All points within `radius` of one query (Open3D search_radius_vector_xd).
    SearchResult search_radius_vector_xd(const std::vector<double>& query, double radius) const {
        return search_xd(query.data(), 1, query.size(), SearchParam::Radius(radius));
    }
    /// @brief At most `max_nn` nearest points within `radius` (Open3D search_hybrid_vector_xd).
    SearchResult search_hybrid_vector_xd(const std::vector<double>& query, double radius, int max_nn) const {
        return search_xd(query.data(), 1, query.size(), SearchParam::Hybrid(radius, max_nn));
    }

private:
    template <typename F>
    static SearchResult run(const SearchParam& param, F&& search) {
        const o3d_search_param_t c = param.to_c();
        return SearchResult::adopt([&](o3d_search_result_t** o) { return search(o, &c); });
    }
    static std::size_t rows_of(std::size_t size, std::size_t dimension) {
        if (dimension == 0 ? size != 0 : size % dimension != 0)
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::KDTreeFlann: " + std::to_string(size) +
                                                        " values are not whole points of dimension " +
                                                        std::to_string(dimension));
        return dimension == 0 ? 0 : size / dimension;
    }
};

}  // namespace o3dpp
