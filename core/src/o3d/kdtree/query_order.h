// SPDX-License-Identifier: MIT
#pragma once
/// @file query_order.h
/// @brief Internal: a cache-friendly visiting order for batch queries (Morton / Z-order curve).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace o3d::kdtree {

/// @brief A permutation of [0, points.size()) that visits nearby points one after another.
/// Small inputs, or inputs that do not fit 32-bit indices, get the identity. Pure function of the
/// input (deterministic). Points must be finite.
std::vector<uint32_t> spatial_order(const std::vector<Eigen::Vector3d>& points);

}  // namespace o3d::kdtree
