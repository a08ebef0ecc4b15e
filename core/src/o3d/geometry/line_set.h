// SPDX-License-Identifier: MIT
#pragma once
/// @file line_set.h
/// @brief The line-set container: points, lines between them (point indices) and per-line colors.
#include <Eigen/Core>
#include <vector>

namespace o3d::geometry {

/// @brief Line indices are not trusted: algorithms check them before following them.
/// Colors count only when there is one per line (Open3D semantics).
struct LineSet {
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector2i> lines;
    std::vector<Eigen::Vector3d> colors;

    bool has_points() const { return !points.empty(); }
    bool has_lines() const { return !points.empty() && !lines.empty(); }
    bool has_colors() const { return has_lines() && colors.size() == lines.size(); }
};

}  // namespace o3d::geometry
