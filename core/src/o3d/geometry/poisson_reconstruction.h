// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_reconstruction.h
/// @brief Screened Poisson surface reconstruction (Kazhdan & Hoppe 2013) on an adaptive octree, with
/// Open3D's TriangleMesh.create_from_point_cloud_poisson parameters and outputs.
#include <functional>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

struct PoissonOptions {
    int depth = 8;             ///< maximum octree depth (Open3D's default); valid range [1, 16]
    double width = 0.0;        ///< > 0: finest cell width; sets the depth (as PoissonRecon/Open3D do); 0 = use depth
    double scale = 1.1;        ///< ratio of the reconstruction cube's side to the samples' bounding cube
    bool linear_fit = false;   ///< place iso-vertices by linear interpolation (true) or as Open3D does otherwise
    int num_threads = 0;       ///< 0 = library default; the result must not depend on it
    std::function<bool(double)> progress;  ///< fraction done in [0,1]; return false to cancel (throw o3d::Cancelled)
    double point_weight = 4.0; ///< screening weight alpha (Open3D/PoissonRecon default 4); >= 0, 0 = unscreened
    /// Treat the reconstruction cube's boundary as outside, so surfaces that would leave the cube (open scans)
    /// are closed along it and the mesh is always watertight. Off = Open3D's behaviour (open there).
    bool close_boundary = false;
};

struct PoissonResult {
    TriangleMesh mesh;             ///< vertices, triangles (outward), vertex_colors when the cloud has colors
    std::vector<double> densities; ///< one per vertex, as Open3D returns them
};

/// @brief Reconstructs a closed surface from an oriented point cloud: the indicator-like function chi whose
/// gradient fits the samples' normal field, screened towards 1/2 at the samples, solved coarse to fine on an
/// octree refined only near the samples, each down to the depth its sampling density supports (at most
/// `depth`); its iso-surface at the mean sample value is triangulated on the octree's leaves, so surfaces
/// bridging unsampled regions come out on coarse cells. densities[i] is the local sampling density at vertex i expressed as an octree depth (about
/// depth-4 .. depth+1; low where the surface bridges unsampled regions).
/// @throws InvalidArgument: empty cloud, no normals, non-finite point/normal, depth outside [1,16], width < 0,
///   scale <= 0 or non-finite, point_weight < 0 or non-finite, a width giving a depth above 16; Cancelled.
PoissonResult create_from_point_cloud_poisson(const PointCloud& cloud, const PoissonOptions& options = {});

}  // namespace o3d::geometry
