// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_filter_detail.h
/// @brief Internal: the vertex-filter driver shared by the smoothing filters and filter_sharpen (one neighbour
/// walk, one double-buffered iteration, one treatment of the scope and of triangle normals).
#include <vector>

#include "o3d/geometry/mesh_smoothing.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry::detail {

/// @brief What one step does to each selected attribute x of vertex v with neighbours N (ascending):
/// Mean: (x_v + sum x_n) / (1 + |N|); Laplacian: x_v + weight (weighted mean of x_n - x_v), weights
/// 1 / (|p_v - p_n| + 1e-12) from the positions; Sharpen: x_v + weight (|N| x_v - sum x_n).
enum class FilterStepKind { Mean, Laplacian, Sharpen };
struct FilterStep {
    FilterStepKind kind;
    double weight;
};

/// @brief InvalidArgument on bad triangles, no vertices, a negative iteration count or an unknown scope.
void check_filter_input(const TriangleMesh& mesh, int number_of_iterations, FilterScope scope);

/// @brief `number_of_iterations` times, each step in order, every vertex from the previous state; attributes
/// outside `scope` are copied, a vertex without neighbours keeps its values, triangle normals are recomputed
/// when the positions moved. Deterministic for any thread count.
TriangleMesh apply_vertex_filter(const TriangleMesh& mesh, int number_of_iterations,
                                 const std::vector<FilterStep>& steps, FilterScope scope, int num_threads);

}  // namespace o3d::geometry::detail
