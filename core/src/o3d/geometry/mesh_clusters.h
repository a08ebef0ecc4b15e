// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_clusters.h
/// @brief Edge-connected triangle components (Open3D's cluster_connected_triangles).
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

struct TriangleClusters {
    std::vector<int> triangle_cluster;  ///< cluster of each triangle; clusters numbered by lowest triangle
    std::vector<int> cluster_size;      ///< triangles in each cluster
    std::vector<double> cluster_area;   ///< area of each cluster, summed in triangle order
};

/// @brief Triangles sharing an edge (two vertex indices) are in one cluster. @throws InvalidArgument on an
/// out-of-range triangle index.
TriangleClusters cluster_connected_triangles(const TriangleMesh& mesh);

}  // namespace o3d::geometry
