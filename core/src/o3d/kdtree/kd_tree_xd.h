// SPDX-License-Identifier: MIT
#pragma once
/// @file kd_tree_xd.h
/// @brief Exact KD-tree over points of any dimension (FLANN's KDTreeSingleIndex), e.g. 33-D FPFH
/// descriptors (Open3D's KDTreeFlann built from a Feature). Owns a copy of its points; all searches
/// are const and safe to run concurrently.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

#include "o3d/kdtree/kd_tree.h"

namespace o3d::kdtree {

class KDTreeXd {
public:
    /// @brief Index the columns of `points` (dimension x n, column i = point i, as a Feature stores
    /// its descriptors). Taken by value: pass std::move to avoid the copy.
    /// @throws o3d::InvalidArgument on a non-finite value, dimension 0 with points, or >= 2^31 - 1 points.
    explicit KDTreeXd(Eigen::MatrixXd points);
    ~KDTreeXd();
    KDTreeXd(const KDTreeXd&) = delete;
    KDTreeXd& operator=(const KDTreeXd&) = delete;

    size_t dimension() const;
    size_t size() const;
    /// @brief The indexed points, dimension x size.
    const Eigen::MatrixXd& points() const;

    /// @brief The `knn` nearest points to `query` (dimension() doubles), ascending. Returns the count.
    /// A non-finite query finds nothing.
    int search_knn(const double* query, int knn, std::vector<int>& indices, std::vector<double>& distances2) const;
    /// @brief All points within `radius`, ascending. Returns the count.
    int search_radius(const double* query, double radius, std::vector<int>& indices,
                      std::vector<double>& distances2) const;
    /// @brief At most `max_nn` nearest points within `radius`, ascending. Returns the count.
    int search_hybrid(const double* query, double radius, int max_nn, std::vector<int>& indices,
                      std::vector<double>& distances2) const;
    /// @brief Dispatch on `param.kind`. @throws o3d::InvalidArgument on a bad parameter.
    int search(const double* query, const SearchParam& param, std::vector<int>& indices,
               std::vector<double>& distances2) const;
    /// @brief Index of the nearest point (squared distance out), or -1 for an empty tree or a
    /// non-finite query.
    int search_nearest(const double* query, double& distance2) const;

    /// @brief Batch search of `num_queries` queries stored one after another (dimension() doubles
    /// each: row-major rows, or the columns of a dimension x n matrix), in parallel
    /// (num_threads 0 = default). Deterministic: the output does not depend on the thread count.
    /// @throws o3d::InvalidArgument on a bad parameter, a NULL `queries` with num_queries > 0 or a
    /// non-finite query value.
    SearchResult search_batch(const double* queries, size_t num_queries, const SearchParam& param,
                              int num_threads = 0) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace o3d::kdtree
