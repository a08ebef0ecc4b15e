// SPDX-License-Identifier: MIT
#include "o3d/kdtree/kd_tree_xd.h"

#include <flann/algorithms/dist.h>
#include <flann/algorithms/kdtree_single_index.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "o3d/kdtree/result_sets.h"
#include "o3d/kdtree/tree_searches.h"
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
    return detail::search_knn(*impl_, size(), query, knn, indices, distances2);
}

int KDTreeXd::search_radius(const double* query, double radius, std::vector<int>& indices,
                            std::vector<double>& distances2) const {
    return detail::search_radius(*impl_, query, radius, indices, distances2);
}

int KDTreeXd::search_hybrid(const double* query, double radius, int max_nn, std::vector<int>& indices,
                            std::vector<double>& distances2) const {
    return detail::search_hybrid(*impl_, size(), query, radius, max_nn, indices, distances2);
}

int KDTreeXd::search(const double* query, const SearchParam& param, std::vector<int>& indices,
                     std::vector<double>& distances2) const {
    return detail::search(*impl_, size(), query, param, indices, distances2);
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
    return detail::search_batch(
        *impl_, size(), nq, [&](size_t q) { return queries + q * dim; }, [](size_t j) { return j; }, kChunk, param,
        threads);
}

}  // namespace o3d::kdtree
