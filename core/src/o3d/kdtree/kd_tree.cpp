// SPDX-License-Identifier: MIT
#include "o3d/kdtree/kd_tree.h"

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "o3d/kdtree/query_order.h"
#include "o3d/kdtree/result_sets.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::kdtree {
namespace {

using FlannIndex = flann::KDTreeSingleIndex<flann::L2_3D<double>>;

// Leaves of ~15 points: fewer, shallower nodes than FLANN's default 10, which pays off for the
// knn = 30 neighbourhoods that normals and features use, and barely costs single-nearest queries.
constexpr int kLeafMaxSize = 15;
// Queries searched per task: small enough to balance threads, large enough to amortise scheduling.
constexpr size_t kChunk = 1024;

double square(double x) { return x * x; }

}  // namespace

void validate(const SearchParam& param) {
    switch (param.kind) {
        case SearchParam::Kind::Knn:
            if (param.knn < 1) throw InvalidArgument("knn must be >= 1, got " + std::to_string(param.knn));
            return;
        case SearchParam::Kind::Hybrid:
            if (param.knn < 1) throw InvalidArgument("max_nn must be >= 1, got " + std::to_string(param.knn));
            [[fallthrough]];
        case SearchParam::Kind::Radius:
            if (!std::isfinite(param.radius) || param.radius <= 0.0)
                throw InvalidArgument("radius must be finite and > 0, got " + std::to_string(param.radius));
            return;
    }
    throw InvalidArgument("unknown search kind");
}

struct KDTree::Impl {
    std::vector<Eigen::Vector3d> points;
    std::unique_ptr<FlannIndex> index;  // null for an empty tree
    flann::SearchParams exact;          // eps 0, unsorted: the result sets sort themselves

    Impl() { exact.sorted = false; }

    /// @brief Up to `capacity` nearest points closer than sqrt(bound2), sorted; returns the count.
    size_t knn(const Eigen::Vector3d& q, size_t capacity, double bound2, int32_t* idx, double* d2) const {
        if (!index || capacity == 0 || !q.allFinite()) return 0;
        detail::BoundedKnnSet set(idx, d2, capacity, bound2);
        index->findNeighbors(set, q.data(), exact);
        return set.count();
    }

    /// @brief All points closer than sqrt(radius2), sorted, into the reused `hits`.
    void radius(const Eigen::Vector3d& q, double radius2, std::vector<std::pair<double, int32_t>>& hits) const {
        hits.clear();
        if (!index || !q.allFinite()) return;
        detail::RadiusSet set(hits, radius2);
        index->findNeighbors(set, q.data(), exact);
        set.sort();
    }
};

KDTree::KDTree(std::vector<Eigen::Vector3d> points) : impl_(std::make_unique<Impl>()) {
    if (points.size() >= static_cast<size_t>(std::numeric_limits<int32_t>::max()))
        throw InvalidArgument("a KD-tree holds at most 2^31 - 2 points, got " + std::to_string(points.size()));
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
    impl_->points = std::move(points);
    if (impl_->points.empty()) return;
    // FLANN copies the data in leaf order (reorder = true), so searches touch memory sequentially.
    flann::Matrix<double> data(impl_->points[0].data(), impl_->points.size(), 3);
    impl_->index = std::make_unique<FlannIndex>(data, flann::KDTreeSingleIndexParams(kLeafMaxSize, true));
    impl_->index->buildIndex();
}

KDTree::~KDTree() = default;

size_t KDTree::size() const { return impl_->points.size(); }

const std::vector<Eigen::Vector3d>& KDTree::points() const { return impl_->points; }

int KDTree::search_knn(const Eigen::Vector3d& query, int knn, std::vector<int>& indices,
                       std::vector<double>& distances2) const {
    const size_t capacity = knn > 0 ? std::min(static_cast<size_t>(knn), size()) : 0;
    indices.resize(capacity);
    distances2.resize(capacity);
    static_assert(sizeof(int) == sizeof(int32_t), "indices are written as int32_t");
    const size_t found = impl_->knn(query, capacity, std::numeric_limits<double>::infinity(),
                                    reinterpret_cast<int32_t*>(indices.data()), distances2.data());
    indices.resize(found);
    distances2.resize(found);
    return static_cast<int>(found);
}

int KDTree::search_radius(const Eigen::Vector3d& query, double radius, std::vector<int>& indices,
                          std::vector<double>& distances2) const {
    indices.clear();
    distances2.clear();
    if (!(radius > 0.0)) return 0;
    thread_local std::vector<std::pair<double, int32_t>> hits;
    impl_->radius(query, square(radius), hits);
    indices.reserve(hits.size());
    distances2.reserve(hits.size());
    for (const auto& [d2, i] : hits) {
        indices.push_back(i);
        distances2.push_back(d2);
    }
    return static_cast<int>(hits.size());
}

int KDTree::search_hybrid(const Eigen::Vector3d& query, double radius, int max_nn, std::vector<int>& indices,
                          std::vector<double>& distances2) const {
    const size_t capacity = (max_nn > 0 && radius > 0.0) ? std::min(static_cast<size_t>(max_nn), size()) : 0;
    indices.resize(capacity);
    distances2.resize(capacity);
    const size_t found = impl_->knn(query, capacity, square(radius), reinterpret_cast<int32_t*>(indices.data()),
                                    distances2.data());
    indices.resize(found);
    distances2.resize(found);
    return static_cast<int>(found);
}

int KDTree::search(const Eigen::Vector3d& query, const SearchParam& param, std::vector<int>& indices,
                   std::vector<double>& distances2) const {
    validate(param);
    switch (param.kind) {
        case SearchParam::Kind::Knn: return search_knn(query, param.knn, indices, distances2);
        case SearchParam::Kind::Radius: return search_radius(query, param.radius, indices, distances2);
        case SearchParam::Kind::Hybrid: return search_hybrid(query, param.radius, param.knn, indices, distances2);
    }
    return 0;
}

int KDTree::search_nearest(const Eigen::Vector3d& query, double max_distance, double& distance2) const {
    int32_t index = -1;
    double d2 = 0.0;
    if (!(max_distance > 0.0)) return -1;
    const double bound2 = std::isinf(max_distance) ? max_distance : square(max_distance);
    if (impl_->knn(query, 1, bound2, &index, &d2) == 0) return -1;
    distance2 = d2;
    return index;
}

SearchResult KDTree::search_batch(const std::vector<Eigen::Vector3d>& queries, const SearchParam& param,
                                  int num_threads) const {
    validate(param);
    for (size_t i = 0; i < queries.size(); ++i)
        if (!queries[i].allFinite())
            throw InvalidArgument("query " + std::to_string(i) + " has a non-finite coordinate");
    const int threads = utility::resolve_num_threads(num_threads);
    const size_t nq = queries.size();
    // Visiting queries in space-filling-curve order keeps the tree's hot nodes in cache; each
    // query's answer is still written to its own slot, so the output is in query order.
    const std::vector<uint32_t> order = spatial_order(queries);
    const int64_t num_chunks = static_cast<int64_t>((nq + kChunk - 1) / kChunk);
    SearchResult result;
    result.offsets.assign(nq + 1, 0);

    if (param.kind == SearchParam::Kind::Knn) {
        // Every finite query finds exactly min(knn, size) points: write straight into the output.
        const size_t k = std::min(static_cast<size_t>(param.knn), size());
        for (size_t i = 0; i <= nq; ++i) result.offsets[i] = static_cast<int64_t>(i * k);
        result.indices.resize(nq * k);
        result.distances2.resize(nq * k);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (int64_t c = 0; c < num_chunks; ++c) {
            const size_t end = std::min(nq, static_cast<size_t>(c + 1) * kChunk);
            for (size_t j = static_cast<size_t>(c) * kChunk; j < end; ++j) {
                const size_t q = order[j];
                // data() + offset, not &v[i]: with an empty tree k == 0 and the vectors are empty.
                impl_->knn(queries[q], k, std::numeric_limits<double>::infinity(), result.indices.data() + q * k,
                           result.distances2.data() + q * k);
            }
        }
        return result;
    }

    // Radius / hybrid: variable counts. Chunks of the visiting order (fixed size, so the split does
    // not depend on the thread count) fill their own buffers; each query remembers where its answer
    // lies, and a final pass gathers the answers in query order.
    struct Chunk {
        std::vector<int32_t> indices;
        std::vector<double> distances2;
    };
    std::vector<Chunk> chunks(static_cast<size_t>(num_chunks));
    std::vector<size_t> counts(nq, 0), local_start(nq, 0);
    const bool hybrid = param.kind == SearchParam::Kind::Hybrid;
    const size_t k = hybrid ? std::min(static_cast<size_t>(param.knn), size()) : 0;
    const double radius2 = square(param.radius);
#pragma omp parallel num_threads(threads)
    {
        std::vector<std::pair<double, int32_t>> hits;
        std::vector<int32_t> idx(k);
        std::vector<double> d2(k);
#pragma omp for schedule(dynamic, 1)
        for (int64_t c = 0; c < num_chunks; ++c) {
            Chunk& chunk = chunks[static_cast<size_t>(c)];
            const size_t end = std::min(nq, static_cast<size_t>(c + 1) * kChunk);
            for (size_t j = static_cast<size_t>(c) * kChunk; j < end; ++j) {
                const size_t q = order[j];
                local_start[q] = chunk.indices.size();
                if (hybrid) {
                    const size_t found = impl_->knn(queries[q], k, radius2, idx.data(), d2.data());
                    chunk.indices.insert(chunk.indices.end(), idx.begin(), idx.begin() + found);
                    chunk.distances2.insert(chunk.distances2.end(), d2.begin(), d2.begin() + found);
                    counts[q] = found;
                } else {
                    impl_->radius(queries[q], radius2, hits);
                    for (const auto& [dist, i] : hits) {
                        chunk.indices.push_back(i);
                        chunk.distances2.push_back(dist);
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
        const size_t q = order[static_cast<size_t>(j)];
        const Chunk& chunk = chunks[static_cast<size_t>(j) / kChunk];
        const size_t from = local_start[q], to = static_cast<size_t>(result.offsets[q]);
        std::copy_n(chunk.indices.begin() + static_cast<std::ptrdiff_t>(from), counts[q],
                    result.indices.begin() + static_cast<std::ptrdiff_t>(to));
        std::copy_n(chunk.distances2.begin() + static_cast<std::ptrdiff_t>(from), counts[q],
                    result.distances2.begin() + static_cast<std::ptrdiff_t>(to));
    }
    return result;
}

}  // namespace o3d::kdtree
