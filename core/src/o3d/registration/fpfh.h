// SPDX-License-Identifier: MIT
#pragma once
/// @file fpfh.h
/// @brief Fast Point Feature Histograms (Rusu et al. 2009) with Open3D's definition.
#include <cstdint>
#include <optional>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/feature.h"

namespace o3d::registration {

/// @brief FPFH descriptors, 33 x N, as Open3D's compute_fpfh_feature.
///
/// Each point's neighbourhood is the search `param` over the whole cloud, the point itself counted as
/// the first neighbour. Its SPFH is three 11-bin histograms (the angle atan2 in [-pi, pi], and two
/// cosines in [-1, 1]) of the Darboux-frame pair features with its other neighbours, each summing to
/// 100. Its FPFH is the neighbours' SPFHs weighted by 1 / squared distance (coincident points skipped),
/// each sub-histogram rescaled to sum to 100, plus its own SPFH: so each sub-histogram sums to 200.
/// A point with fewer than 2 neighbours gets a zero descriptor. Neighbourhoods are the KD-tree
/// search's; where points tie at a hybrid search's max_nn cut, the smaller indices are kept (Open3D keeps
/// whichever its tree meets first). Equal to Open3D 0.20's compute_fpfh_feature to rounding.
///
/// With `indices`, only those points get a descriptor: duplicates count once and the columns come in
/// ascending point order (Open3D's mask semantics); neighbourhoods still come from the whole cloud and
/// the values equal the matching columns of the full result.
/// The result does not depend on num_threads (0 = default).
/// @throws InvalidArgument when the cloud has no normals, a point or normal is not finite, the search
/// parameter is bad, an index is out of range or num_threads < 0.
Feature compute_fpfh_feature(const geometry::PointCloud& cloud,
                             const kdtree::SearchParam& param = kdtree::SearchParam::make_knn(30),
                             const std::optional<std::vector<int64_t>>& indices = std::nullopt, int num_threads = 0);

}  // namespace o3d::registration
