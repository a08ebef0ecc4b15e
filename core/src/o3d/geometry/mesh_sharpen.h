// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_sharpen.h
/// @brief Mesh sharpening (Open3D's TriangleMesh.filter_sharpen), the opposite of filter_smooth_simple.
#include "o3d/geometry/mesh_smoothing.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Each vertex (and its normal / color, per `scope`) moves away from its neighbours (vertices that
/// share a triangle side with it): v + strength * (|N| v - sum of the neighbours), `number_of_iterations`
/// times, every vertex from the previous iteration's values (Open3D's defaults: 1 iteration, strength 1,
/// FilterScope::All). Colors are not clamped (Open3D 0.20 leaves them outside [0, 1] too). Conventions as
/// mesh_smoothing.h: attributes outside `scope` are copied unchanged (Open3D leaves them uninitialised for
/// 0 iterations), a vertex without neighbours keeps its value, triangles, UVs, material ids and textures are
/// kept, triangle normals are recomputed when the input had them and the positions moved (Open3D drops
/// them). Deterministic for any thread count (neighbours are summed in ascending order).
/// @throws InvalidArgument on bad triangle indices, no vertices, a negative iteration count, a bad scope or
/// a non-finite strength.
TriangleMesh filter_sharpen(const TriangleMesh& mesh, int number_of_iterations, double strength, FilterScope scope,
                            int num_threads = 0);

}  // namespace o3d::geometry
