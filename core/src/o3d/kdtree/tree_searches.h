// SPDX-License-Identifier: MIT
#pragma once
/// @file tree_searches.h
/// @brief Internal: the single-query and batch searches shared by the 3-D tree (kd_tree.cpp) and the
/// tree of any dimension (kd_tree_xd.cpp). Both trees' Impl answer two primitives on a query of their
/// own type (Eigen::Vector3d or a pointer to `dimension` doubles):
///   size_t knn(query, capacity, bound2, int32_t* idx, double* d2) -> count, sorted, closer than sqrt(bound2)
///   void radius(query, radius2, std::vector<std::pair<double, int32_t>>& hits), sorted
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "o3d/kdtree/kd_tree.h"

namespace o3d::kdtree::detail {

inline double square(double x) { return x * x; }

/// @brief Up to `capacity` nearest points within sqrt(bound2) into the resized vectors; returns the count.
template <class Impl, class Query>
int bounded_knn(const Impl& impl, const Query& query, size_t capacity, double bound2, std::vector<int>& indices,
                std::vector<double>& distances2) {
    indices.resize(capacity);
    distances2.resize(capacity);
    static_assert(sizeof(int) == sizeof(int32_t), "indices are written as int32_t");
    const size_t found =
        impl.knn(query, capacity, bound2, reinterpret_cast<int32_t*>(indices.data()), distances2.data());
    indices.resize(found);
    distances2.resize(found);
    return static_cast<int>(found);
}

template <class Impl, class Query>
int search_knn(const Impl& impl, size_t size, const Query& query, int knn, std::vector<int>& indices,
               std::vector<double>& distances2) {
    const size_t capacity = knn > 0 ? std::min(static_cast<size_t>(knn), size) : 0;
    return bounded_knn(impl, query, capacity, std::numeric_limits<double>::infinity(), indices, distances2);
}

template <class Impl, class Query>
int search_radius(const Impl& impl, const Query& query, double radius, std::vector<int>& indices,
                  std::vector<double>& distances2) {
    indices.clear();
    distances2.clear();
    if (!(radius > 0.0)) return 0;
    thread_local std::vector<std::pair<double, int32_t>> hits;
    impl.radius(query, square(radius), hits);
    indices.reserve(hits.size());
    distances2.reserve(hits.size());
    for (const auto& [d2, i] : hits) {
        indices.push_back(i);
        distances2.push_back(d2);
    }
    return static_cast<int>(hits.size());
}

template <class Impl, class Query>
int search_hybrid(const Impl& impl, size_t size, const Query& query, double radius, int max_nn,
                  std::vector<int>& indices, std::vector<double>& distances2) {
    const size_t capacity = (max_nn > 0 && radius > 0.0) ? std::min(static_cast<size_t>(max_nn), size) : 0;
    return bounded_knn(impl, query, capacity, square(radius), indices, distances2);
}

template <class Impl, class Query>
int search(const Impl& impl, size_t size, const Query& query, const SearchParam& param, std::vector<int>& indices,
           std::vector<double>& distances2) {
    validate(param);
    switch (param.kind) {
        case SearchParam::Kind::Knn: return search_knn(impl, size, query, param.knn, indices, distances2);
        case SearchParam::Kind::Radius: return search_radius(impl, query, param.radius, indices, distances2);
        case SearchParam::Kind::Hybrid:
            return search_hybrid(impl, size, query, param.radius, param.knn, indices, distances2);
    }
    return 0;
}

/// @brief Batch search of `nq` queries (query_at(q)), visited in the order order_at(0 .. nq-1) in chunks of
/// `chunk` (fixed, so the split never depends on the thread count); answers land in query order.
/// The caller has validated `param` and the queries.
template <class Impl, class QueryAt, class OrderAt>
SearchResult search_batch(const Impl& impl, size_t size, size_t nq, QueryAt query_at, OrderAt order_at,
                          size_t chunk, const SearchParam& param, int threads) {
    const int64_t num_chunks = static_cast<int64_t>((nq + chunk - 1) / chunk);
    SearchResult result;
    result.offsets.assign(nq + 1, 0);

    if (param.kind == SearchParam::Kind::Knn) {
        // Every finite query finds exactly min(knn, size) points: write straight into the output.
        const size_t k = std::min(static_cast<size_t>(param.knn), size);
        for (size_t i = 0; i <= nq; ++i) result.offsets[i] = static_cast<int64_t>(i * k);
        result.indices.resize(nq * k);
        result.distances2.resize(nq * k);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (int64_t c = 0; c < num_chunks; ++c) {
            const size_t end = std::min(nq, static_cast<size_t>(c + 1) * chunk);
            for (size_t j = static_cast<size_t>(c) * chunk; j < end; ++j) {
                const size_t q = order_at(j);
                // data() + offset, not &v[i]: with an empty tree k == 0 and the vectors are empty.
                impl.knn(query_at(q), k, std::numeric_limits<double>::infinity(), result.indices.data() + q * k,
                         result.distances2.data() + q * k);
            }
        }
        return result;
    }

    // Radius / hybrid: variable counts. Chunks of the visiting order fill their own buffers; each query
    // remembers where its answer lies, and a final pass gathers the answers in query order.
    struct Chunk {
        std::vector<int32_t> indices;
        std::vector<double> distances2;
    };
    std::vector<Chunk> chunks(static_cast<size_t>(num_chunks));
    std::vector<size_t> counts(nq, 0), local_start(nq, 0);
    const bool hybrid = param.kind == SearchParam::Kind::Hybrid;
    const size_t k = hybrid ? std::min(static_cast<size_t>(param.knn), size) : 0;
    const double radius2 = square(param.radius);
#pragma omp parallel num_threads(threads)
    {
        std::vector<std::pair<double, int32_t>> hits;
        std::vector<int32_t> idx(k);
        std::vector<double> d2(k);
#pragma omp for schedule(dynamic, 1)
        for (int64_t c = 0; c < num_chunks; ++c) {
            Chunk& out = chunks[static_cast<size_t>(c)];
            const size_t end = std::min(nq, static_cast<size_t>(c + 1) * chunk);
            for (size_t j = static_cast<size_t>(c) * chunk; j < end; ++j) {
                const size_t q = order_at(j);
                local_start[q] = out.indices.size();
                if (hybrid) {
                    const size_t found = impl.knn(query_at(q), k, radius2, idx.data(), d2.data());
                    out.indices.insert(out.indices.end(), idx.begin(), idx.begin() + found);
                    out.distances2.insert(out.distances2.end(), d2.begin(), d2.begin() + found);
                    counts[q] = found;
                } else {
                    impl.radius(query_at(q), radius2, hits);
                    for (const auto& [dist, i] : hits) {
                        out.indices.push_back(i);
                        out.distances2.push_back(dist);
                    }
                    counts[q] = hits.size();
                }
            }
        }
    }
    for (size_t q = 0; q < nq; ++q) result.offsets[q + 1] = result.offsets[q] + static_cast<int64_t>(counts[q]);
    const size_t total = static_cast<size_t>(result.offsets[nq]);
    result.indices.resize(total);
    result.distances2.resize(total);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t j = 0; j < static_cast<int64_t>(nq); ++j) {
        const size_t q = order_at(static_cast<size_t>(j));
        const Chunk& from_chunk = chunks[static_cast<size_t>(j) / chunk];
        const size_t from = local_start[q], to = static_cast<size_t>(result.offsets[q]);
        std::copy_n(from_chunk.indices.begin() + static_cast<std::ptrdiff_t>(from), counts[q],
                    result.indices.begin() + static_cast<std::ptrdiff_t>(to));
        std::copy_n(from_chunk.distances2.begin() + static_cast<std::ptrdiff_t>(from), counts[q],
                    result.distances2.begin() + static_cast<std::ptrdiff_t>(to));
    }
    return result;
}

}  // namespace o3d::kdtree::detail
