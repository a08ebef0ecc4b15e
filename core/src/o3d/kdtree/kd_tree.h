// SPDX-License-Identifier: MIT
#pragma once
/// @file kd_tree.h
/// @brief 3-D KD-tree over FLANN's KDTreeSingleIndex. Owns a copy of its points, so it outlives
/// the cloud it was built from. All searches are const and safe to run concurrently.
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace o3d::kdtree {

/// @brief KDTreeSearchParamKNN / Radius / Hybrid.
struct SearchParam {
    enum class Kind { Knn, Radius, Hybrid };
    Kind kind = Kind::Knn;
    int knn = 30;         ///< neighbours for Knn / Hybrid (max_nn)
    double radius = 0.0;  ///< radius for Radius / Hybrid

    static SearchParam make_knn(int k) { return {Kind::Knn, k, 0.0}; }
    static SearchParam make_radius(double r) { return {Kind::Radius, 0, r}; }
    static SearchParam make_hybrid(double r, int max_nn) { return {Kind::Hybrid, max_nn, r}; }
};

/// @brief Throw o3d::InvalidArgument unless `param` is usable: knn / max_nn >= 1, radius finite and > 0.
void validate(const SearchParam& param);

/// @brief Flat results of a batch search: neighbours of query i are [offsets[i], offsets[i+1]).
struct SearchResult {
    std::vector<int64_t> offsets;  ///< num_queries + 1 entries, offsets[0] = 0
    std::vector<int32_t> indices;
    std::vector<double> distances2;  ///< squared distances, ascending within a query
};

class KDTree {
public:
    /// @brief Index `points` (taken by value: pass std::move to avoid the copy).
    /// @throws o3d::InvalidArgument on a non-finite coordinate.
    explicit KDTree(std::vector<Eigen::Vector3d> points);
    ~KDTree();
    KDTree(const KDTree&) = delete;
    KDTree& operator=(const KDTree&) = delete;

    size_t size() const;
    const std::vector<Eigen::Vector3d>& points() const;

    /// @brief The `knn` nearest points, ascending. Returns the count found (<= knn).
    int search_knn(const Eigen::Vector3d& query, int knn, std::vector<int>& indices,
                   std::vector<double>& distances2) const;
    /// @brief All points within `radius`, ascending. Returns the count.
    int search_radius(const Eigen::Vector3d& query, double radius, std::vector<int>& indices,
                      std::vector<double>& distances2) const;
    /// @brief At most `max_nn` nearest points within `radius`, ascending. Returns the count.
    int search_hybrid(const Eigen::Vector3d& query, double radius, int max_nn, std::vector<int>& indices,
                      std::vector<double>& distances2) const;
    /// @brief Dispatch on `param.kind`. @throws o3d::InvalidArgument on a bad parameter.
    int search(const Eigen::Vector3d& query, const SearchParam& param, std::vector<int>& indices,
               std::vector<double>& distances2) const;
    /// @brief Nearest point only: index or -1 when none within `max_distance` (squared distance out).
    int search_nearest(const Eigen::Vector3d& query, double max_distance, double& distance2) const;

    /// @brief Batch search over `queries` in parallel (num_threads 0 = default); deterministic.
    SearchResult search_batch(const std::vector<Eigen::Vector3d>& queries, const SearchParam& param,
                              int num_threads = 0) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace o3d::kdtree
