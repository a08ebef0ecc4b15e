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
#include "o3d/kdtree/tree_searches.h"
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
    return detail::search_knn(*impl_, size(), query, knn, indices, distances2);
}

int KDTree::search_radius(const Eigen::Vector3d& query, double radius, std::vector<int>& indices,
                          std::vector<double>& distances2) const {
    return detail::search_radius(*impl_, query, radius, indices, distances2);
}

int KDTree::search_hybrid(const Eigen::Vector3d& query, double radius, int max_nn, std::vector<int>& indices,
                          std::vector<double>& distances2) const {
    return detail::search_hybrid(*impl_, size(), query, radius, max_nn, indices, distances2);
}

int KDTree::search(const Eigen::Vector3d& query, const SearchParam& param, std::vector<int>& indices,
                   std::vector<double>& distances2) const {
    return detail::search(*impl_, size(), query, param, indices, distances2);
}

int KDTree::search_nearest(const Eigen::Vector3d& query, double max_distance, double& distance2) const {
    int32_t index = -1;
    double d2 = 0.0;
    if (!(max_distance > 0.0)) return -1;
    const double bound2 = std::isinf(max_distance) ? max_distance : detail::square(max_distance);
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
    // Visiting queries in space-filling-curve order keeps the tree's hot nodes in cache; each
    // query's answer is still written to its own slot, so the output is in query order.
    const std::vector<uint32_t> order = spatial_order(queries);
    return detail::search_batch(
        *impl_, size(), queries.size(), [&](size_t q) -> const Eigen::Vector3d& { return queries[q]; },
        [&](size_t j) { return static_cast<size_t>(order[j]); }, kChunk, param, threads);
}

}  // namespace o3d::kdtree
