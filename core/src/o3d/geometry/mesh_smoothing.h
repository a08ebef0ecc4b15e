// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_smoothing.h
/// @brief Mesh smoothing filters (Open3D's filter_smooth_simple / laplacian / taubin).
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief What a filter changes: positions, normals and colors (All), or one of them.
enum class FilterScope { All = 0, Color = 1, Normal = 2, Vertex = 3 };

/// @brief Each vertex (and its normal / color) becomes the mean of itself and its neighbours (vertices that
/// share a triangle side with it), `number_of_iterations` times, every vertex from the previous iteration.
/// Attributes outside `scope` are copied unchanged (Open3D leaves them uninitialised, and returns garbage
/// for 0 iterations); a vertex without neighbours keeps its value. Triangles, UVs, material ids and textures
/// are kept; triangle normals are recomputed when the input had them and the positions moved.
/// Deterministic for any thread count (neighbours are summed in ascending order).
/// @throws InvalidArgument on bad triangle indices, no vertices, a negative iteration count or a bad scope.
TriangleMesh filter_smooth_simple(const TriangleMesh& mesh, int number_of_iterations, FilterScope scope,
                                  int num_threads = 0);

/// @brief Laplacian step v += lambda * (weighted mean of neighbours - v), `number_of_iterations` times, with
/// Open3D's weights 1 / (|v - neighbour| + 1e-12) (computed from the positions, for every attribute).
/// Otherwise as filter_smooth_simple. @throws as filter_smooth_simple, or on a non-finite lambda.
TriangleMesh filter_smooth_laplacian(const TriangleMesh& mesh, int number_of_iterations, double lambda_filter,
                                     FilterScope scope, int num_threads = 0);

/// @brief Taubin smoothing: per iteration a Laplacian step with `lambda_filter`, then one with `mu`
/// (Open3D's defaults 0.5 and -0.53). @throws as filter_smooth_laplacian, or on a non-finite mu.
TriangleMesh filter_smooth_taubin(const TriangleMesh& mesh, int number_of_iterations, double lambda_filter,
                                  double mu, FilterScope scope, int num_threads = 0);

}  // namespace o3d::geometry
