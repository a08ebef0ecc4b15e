// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_orientation.h
/// @brief Consistent triangle winding (Open3D's TriangleMesh.orient_triangles).
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Turn triangles over so that every edge shared by two triangles is walked once in each direction.
/// Triangles joined through such edges form components; in each, the lowest-index triangle keeps its
/// winding (Open3D starts each component from a hash-set order, so its choice of side may differ) and the
/// others follow it. A turned triangle swaps its last two corners, together with their UVs, and its
/// triangle normal (if present) is negated. Returns false and leaves the mesh unchanged when no consistent
/// orientation exists (is_orientable false: a Moebius strip, an edge with more than two triangles); true
/// for a mesh without triangles. @throws InvalidArgument on an out-of-range triangle index.
bool orient_triangles(TriangleMesh& mesh);

}  // namespace o3d::geometry
