// SPDX-License-Identifier: MIT
#pragma once
/// @file fpfh_neighbourhoods.h
/// @brief Internal to FPFH: the neighbourhoods of cloud points within their own cloud, as the KD-tree
/// search gives them, with the point itself (or a point coincident with it) first.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "o3d/kdtree/kd_tree.h"

namespace o3d::registration::detail {

/// @brief Neighbourhoods of points of one cloud in that cloud. Radius and hybrid searches run on a
/// uniform grid of radius-sized cells (every neighbour lies in the 27 cells around the query's: no tree
/// descent, no per-candidate bookkeeping); KNN searches, clouds too sparse for a grid and hybrid radii
/// spanning far more than max_nn points use the KD-tree. Either way the sets are the KD-tree search's:
/// within the radius (strictly), at most max_nn / knn nearest, squared distances bit-identical; ties
/// at the max_nn cut of a hybrid search go to the smaller index (Open3D's go to whichever its tree
/// meets first), at a KNN cut to the tree's order. Within a set the order is not by distance, except
/// that entry 0 is at distance 0 (the point itself, or a coincident one). Results do not depend on
/// the thread count.
class FpfhNeighbourhoods {
public:
    /// @throws o3d::InvalidArgument on a non-finite point or a bad parameter.
    FpfhNeighbourhoods(const std::vector<Eigen::Vector3d>& points, const kdtree::SearchParam& param);
    ~FpfhNeighbourhoods();
    FpfhNeighbourhoods(const FpfhNeighbourhoods&) = delete;
    FpfhNeighbourhoods& operator=(const FpfhNeighbourhoods&) = delete;

    /// @brief Row j: the neighbourhood of points[which[j]].
    kdtree::SearchResult search(const std::vector<int64_t>& which, int num_threads) const;

private:
    struct Grid;
    /// @brief The neighbourhood of point i into `hits` (idx, d2: scratch for the tree).
    void neighbours(size_t i, std::vector<std::pair<double, int32_t>>& hits, std::vector<int>& idx,
                    std::vector<double>& d2) const;

    const std::vector<Eigen::Vector3d>& points_;
    kdtree::SearchParam param_;
    std::unique_ptr<const kdtree::KDTree> tree_;  // when there is no grid
    std::unique_ptr<const Grid> grid_;
};

}  // namespace o3d::registration::detail
