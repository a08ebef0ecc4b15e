// SPDX-License-Identifier: MIT
#pragma once
/// @file kdtree.hpp
/// @brief o3dpp::KDTreeFlann and o3dpp::SearchResult (flat batch search results).
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/kdtree.h"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief Result of a batch search: for query i, neighbours offsets()[i] .. offsets()[i+1]-1,
/// sorted by increasing distance. Move-only; independent of the tree it came from.
class SearchResult {
public:
    explicit SearchResult(o3d_search_result_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::SearchResult: NULL handle");
    }
    o3d_search_result_t* get() const noexcept { return h_.get(); }
    o3d_search_result_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    std::size_t num_queries() const { return counts()[0]; }
    /// @brief Neighbours over all queries.
    std::size_t total() const { return counts()[1]; }

    // Borrowed views, valid while this SearchResult lives.
    Span<const int64_t> offsets() const {
        View v = view();
        return {v.offsets, num_queries() + 1};
    }
    Span<const int32_t> indices() const { return {view().indices, total()}; }
    Span<const double> distances2() const { return {view().distances2, total()}; }
    /// @brief Neighbour indices of query `i`.
    Span<const int32_t> indices(std::size_t i) const {
        View v = view();
        check_query(i);
        return {v.indices + v.offsets[i], static_cast<std::size_t>(v.offsets[i + 1] - v.offsets[i])};
    }
    /// @brief Squared neighbour distances of query `i`.
    Span<const double> distances2(std::size_t i) const {
        View v = view();
        check_query(i);
        return {v.distances2 + v.offsets[i], static_cast<std::size_t>(v.offsets[i + 1] - v.offsets[i])};
    }

    // Copies.
    std::vector<int64_t> get_offsets() const {
        std::vector<int64_t> out(num_queries() + 1);
        check(o3d_search_result_get_offsets(get(), out.data(), out.size()));
        return out;
    }
    std::vector<int32_t> get_indices() const {
        std::vector<int32_t> out(total());
        check(o3d_search_result_get_indices(get(), out.data(), out.size()));
        return out;
    }
    std::vector<double> get_distances2() const {
        std::vector<double> out(total());
        check(o3d_search_result_get_distances2(get(), out.data(), out.size()));
        return out;
    }

private:
    struct View {
        const int64_t* offsets = nullptr;
        const int32_t* indices = nullptr;
        const double* distances2 = nullptr;
    };
    std::array<std::size_t, 2> counts() const {
        std::array<std::size_t, 2> c{};
        check(o3d_search_result_counts(get(), &c[0], &c[1]));
        return c;
    }
    View view() const {
        View v;
        check(o3d_search_result_view(get(), &v.offsets, &v.indices, &v.distances2));
        return v;
    }
    void check_query(std::size_t i) const {
        if (i >= num_queries()) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::SearchResult: query index out of range");
    }

    UniqueHandle<o3d_search_result_t, &o3d_search_result_destroy> h_;
};

/// @brief KD-tree over 3-D points (copies them: independent of the source cloud). Move-only.
class KDTreeFlann {
public:
    explicit KDTreeFlann(const PointCloud& cloud) {
        o3d_kdtree_t* t = nullptr;
        check(o3d_kdtree_create_from_pointcloud(&t, cloud.get()));
        h_.reset(t);
    }
    KDTreeFlann(const double* xyz, std::size_t n) {
        o3d_kdtree_t* t = nullptr;
        check(o3d_kdtree_create_from_points(&t, xyz, n));
        h_.reset(t);
    }
    explicit KDTreeFlann(const std::vector<Vec3>& points)
        : KDTreeFlann(points.empty() ? nullptr : points.front().data(), points.size()) {}

    o3d_kdtree_t* get() const noexcept { return h_.get(); }
    o3d_kdtree_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    std::size_t size() const {
        size_t n = 0;
        check(o3d_kdtree_size(get(), &n));
        return n;
    }

    /// @brief Batch search of `num_queries` rows of `queries`. num_threads 0 = library default.
    SearchResult search(const double* queries, std::size_t num_queries, const SearchParam& param,
                        int num_threads = 0) const {
        const o3d_search_param_t c = param.to_c();
        o3d_search_result_t* r = nullptr;
        check(o3d_kdtree_search(get(), queries, num_queries, &c, num_threads, &r));
        return SearchResult(r);
    }
    SearchResult search(const float* queries, std::size_t num_queries, const SearchParam& param,
                        int num_threads = 0) const {
        const o3d_search_param_t c = param.to_c();
        o3d_search_result_t* r = nullptr;
        check(o3d_kdtree_search_f32(get(), queries, num_queries, &c, num_threads, &r));
        return SearchResult(r);
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

private:
    UniqueHandle<o3d_kdtree_t, &o3d_kdtree_destroy> h_;
};

}  // namespace o3dpp
