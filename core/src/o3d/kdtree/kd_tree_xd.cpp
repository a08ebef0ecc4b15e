// SPDX-License-Identifier: MIT
#include "o3d/kdtree/kd_tree_xd.h"

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "o3d/kdtree/result_sets.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::kdtree {
namespace {

using FlannIndex = flann::KDTreeSingleIndex<flann::L2<double>>;

// FLANN's default leaf size: high-dimensional trees prune poorly, so deeper trees with small
// leaves do fewer distance computations than the 3-D tree's larger leaves.
constexpr int kLeafMaxSize = 10;
// Queries per task: fixed, so the work split (and the output) never depends on the thread count.
constexpr size_t kChunk = 256;

double square(double x) { return x * x; }

bool all_finite(const double* v, size_t n) {
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

}  // namespace

struct KDTreeXd::Impl {
    Eigen::MatrixXd points;
    std::unique_ptr<FlannIndex> index;  // null for an empty tree
    flann::SearchParams exact;          // eps 0, unsorted: the result sets sort themselves

    Impl() { exact.sorted = false; }

    size_t dim() const { return static_cast<size_t>(points.rows()); }

    size_t knn(const double* q, size_t capacity, double bound2, int32_t* idx, double* d2) const {
        if (!index || capacity == 0 || !all_finite(q, dim())) return 0;
        detail::BoundedKnnSet set(idx, d2, capacity, bound2);
        index->findNeighbors(set, q, exact);
        return set.count();
    }

    void radius(const double* q, double radius2, std::vector<std::pair<double, int32_t>>& hits) const {
        hits.clear();
        if (!index || !all_finite(q, dim())) return;
        detail::RadiusSet set(hits, radius2);
        index->findNeighbors(set, q, exact);
        set.sort();
    }
};

KDTreeXd::KDTreeXd(Eigen::MatrixXd points) : impl_(std::make_unique<Impl>()) {
    const size_t n = static_cast<size_t>(points.cols()), dim = static_cast<size_t>(points.rows());
    if (n >= static_cast<size_t>(std::numeric_limits<int32_t>::max()))
        throw InvalidArgument("a KD-tree holds at most 2^31 - 2 points, got " + std::to_string(n));
    if (n > 0 && dim == 0) throw InvalidArgument("cannot index " + std::to_string(n) + " points of dimension 0");
    for (size_t i = 0; i < n; ++i)
        if (!all_finite(points.col(static_cast<Eigen::Index>(i)).data(), dim))
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite value");
    impl_->points = std::move(points);
    if (n == 0) return;
    // A column-major dimension x n matrix is FLANN's row-major n x dimension layout. FLANN copies the
    // data in leaf order (reorder = true), so searches read memory sequentially.
    flann::Matrix<double> data(impl_->points.data(), n, dim);
    impl_->index = std::make_unique<FlannIndex>(data, flann::KDTreeSingleIndexParams(kLeafMaxSize, true));
    impl_->index->buildIndex();
}

KDTreeXd::~KDTreeXd() = default;

size_t KDTreeXd::dimension() const { return impl_->dim(); }

size_t KDTreeXd::size() const { return static_cast<size_t>(impl_->points.cols()); }

const Eigen::MatrixXd& KDTreeXd::points() const { return impl_->points; }

int KDTreeXd::search_knn(const double* query, int knn, std::vector<int>& indices,
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

int KDTreeXd::search_radius(const double* query, double radius, std::vector<int>& indices,
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

int KDTreeXd::search_hybrid(const double* query, double radius, int max_nn, std::vector<int>& indices,
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

int KDTreeXd::search(const double* query, const SearchParam& param, std::vector<int>& indices,
                     std::vector<double>& distances2) const {
    validate(param);
    switch (param.kind) {
        case SearchParam::Kind::Knn: return search_knn(query, param.knn, indices, distances2);
        case SearchParam::Kind::Radius: return search_radius(query, param.radius, indices, distances2);
        case SearchParam::Kind::Hybrid: return search_hybrid(query, param.radius, param.knn, indices, distances2);
    }
    return 0;
}

int KDTreeXd::search_nearest(const double* query, double& distance2) const {
    int32_t index = -1;
    double d2 = 0.0;
    if (impl_->knn(query, 1, std::numeric_limits<double>::infinity(), &index, &d2) == 0) return -1;
    distance2 = d2;
    return index;
}

SearchResult KDTreeXd::search_batch(const double* queries, size_t num_queries, const SearchParam& param,
                                    int num_threads) const {
    validate(param);
    const size_t dim = dimension(), nq = num_queries;
    if (nq > 0 && !queries) throw InvalidArgument("queries is NULL but num_queries = " + std::to_string(nq));
    for (size_t q = 0; q < nq; ++q)
        if (!all_finite(queries + q * dim, dim))
            throw InvalidArgument("query " + std::to_string(q) + " has a non-finite value");
    const int threads = utility::resolve_num_threads(num_threads);
    const int64_t num_chunks = static_cast<int64_t>((nq + kChunk - 1) / kChunk);
    SearchResult result;
    result.offsets.assign(nq + 1, 0);

    if (param.kind == SearchParam::Kind::Knn) {
        // Every query finds exactly min(knn, size) points: write straight into the output.
        const size_t k = std::min(static_cast<size_t>(param.knn), size());
        for (size_t i = 0; i <= nq; ++i) result.offsets[i] = static_cast<int64_t>(i * k);
        result.indices.resize(nq * k);
        result.distances2.resize(nq * k);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (int64_t c = 0; c < num_chunks; ++c) {
            const size_t end = std::min(nq, static_cast<size_t>(c + 1) * kChunk);
            for (size_t q = static_cast<size_t>(c) * kChunk; q < end; ++q)
                impl_->knn(queries + q * dim, k, std::numeric_limits<double>::infinity(),
                           result.indices.data() + q * k, result.distances2.data() + q * k);
        }
        return result;
    }

    // Radius / hybrid: variable counts. Each chunk fills its own buffers in query order; the
    // chunks are then concatenated in order.
    struct Chunk {
        std::vector<int32_t> indices;
        std::vector<double> distances2;
    };
    std::vector<Chunk> chunks(static_cast<size_t>(num_chunks));
    std::vector<size_t> counts(nq, 0);
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
            for (size_t q = static_cast<size_t>(c) * kChunk; q < end; ++q) {
                if (hybrid) {
                    const size_t found = impl_->knn(queries + q * dim, k, radius2, idx.data(), d2.data());
                    chunk.indices.insert(chunk.indices.end(), idx.begin(), idx.begin() + found);
                    chunk.distances2.insert(chunk.distances2.end(), d2.begin(), d2.begin() + found);
                    counts[q] = found;
                } else {
                    impl_->radius(queries + q * dim, radius2, hits);
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
    result.indices.reserve(static_cast<size_t>(result.offsets[nq]));
    result.distances2.reserve(static_cast<size_t>(result.offsets[nq]));
    for (const Chunk& chunk : chunks) {
        result.indices.insert(result.indices.end(), chunk.indices.begin(), chunk.indices.end());
        result.distances2.insert(result.distances2.end(), chunk.distances2.begin(), chunk.distances2.end());
    }
    return result;
}

}  // namespace o3d::kdtree
