// SPDX-License-Identifier: MIT
// C API: the processing functions of trianglemesh.h (sampling, simplification, smoothing, subdivision,
// cropping, as-rigid-as-possible deformation), each writing a new handle over o3d::geometry.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/mesh_crop.h"
#include "o3d/geometry/mesh_deform_arap.h"
#include "o3d/geometry/mesh_poisson_disk.h"
#include "o3d/geometry/mesh_sampling.h"
#include "o3d/geometry/mesh_simplify_quadric.h"
#include "o3d/geometry/mesh_simplify_vertex_clustering.h"
#include "o3d/geometry/mesh_smoothing.h"
#include "o3d/geometry/mesh_subdivision.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::FilterScope;
using o3d::geometry::PointCloud;
using o3d::geometry::TriangleMesh;

namespace {

template <typename T>
T** require_out(T** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

const TriangleMesh& mesh_of(const o3d_trianglemesh_t* mesh) { return require(mesh, "mesh")->mesh; }

o3d_status emit(o3d_trianglemesh_t** out, TriangleMesh&& result) {
    auto handle = std::make_unique<o3d_trianglemesh>();
    handle->mesh = std::move(result);
    *out = handle.release();
    return O3D_OK;
}

o3d_status emit(o3d_pointcloud_t** out, PointCloud&& result) {
    auto handle = std::make_unique<o3d_pointcloud>();
    handle->cloud = std::move(result);
    *out = handle.release();
    return O3D_OK;
}

FilterScope to_scope(int32_t scope) {
    if (scope < O3D_FILTER_SCOPE_ALL || scope > O3D_FILTER_SCOPE_VERTEX)
        throw o3d::InvalidArgument("filter_scope " + std::to_string(scope) +
                                   " is not one of O3D_FILTER_SCOPE_ALL, _COLOR, _NORMAL, _VERTEX");
    return static_cast<FilterScope>(scope);
}


}  // namespace

extern "C" {

O3D_API o3d_status o3d_trianglemesh_sample_points_uniformly(o3d_pointcloud_t** out, const o3d_trianglemesh_t* mesh,
                                                            size_t number_of_points, int32_t use_triangle_normal,
                                                            uint64_t seed) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::sample_points_uniformly(mesh_of(mesh), number_of_points,
                                                                use_triangle_normal != 0, seed));
    });
}

O3D_API o3d_status o3d_trianglemesh_sample_points_poisson_disk(o3d_pointcloud_t** out,
                                                               const o3d_trianglemesh_t* mesh,
                                                               size_t number_of_points, double init_factor,
                                                               int32_t use_triangle_normal, uint64_t seed) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::sample_points_poisson_disk(mesh_of(mesh), number_of_points, init_factor,
                                                                   use_triangle_normal != 0, seed));
    });
}

O3D_API o3d_status o3d_trianglemesh_simplify_vertex_clustering(o3d_trianglemesh_t** out,
                                                               const o3d_trianglemesh_t* mesh, double voxel_size,
                                                               int32_t contraction) {
    return guard(__func__, [&] {
        require_out(out);
        if (contraction != O3D_SIMPLIFICATION_AVERAGE && contraction != O3D_SIMPLIFICATION_QUADRIC)
            throw o3d::InvalidArgument("contraction " + std::to_string(contraction) +
                                       " is not O3D_SIMPLIFICATION_AVERAGE or O3D_SIMPLIFICATION_QUADRIC");
        const auto how = static_cast<o3d::geometry::SimplificationContraction>(contraction);
        return emit(out, o3d::geometry::simplify_vertex_clustering(mesh_of(mesh), voxel_size, how));
    });
}

O3D_API o3d_status o3d_trianglemesh_simplify_quadric_decimation(o3d_trianglemesh_t** out,
                                                                const o3d_trianglemesh_t* mesh,
                                                                size_t target_number_of_triangles,
                                                                double maximum_error, double boundary_weight) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::simplify_quadric_decimation(mesh_of(mesh), target_number_of_triangles,
                                                                    maximum_error, boundary_weight));
    });
}

O3D_API o3d_status o3d_trianglemesh_filter_smooth_simple(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                         int32_t number_of_iterations, int32_t filter_scope) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::filter_smooth_simple(mesh_of(mesh), number_of_iterations,
                                                             to_scope(filter_scope)));
    });
}

O3D_API o3d_status o3d_trianglemesh_filter_smooth_laplacian(o3d_trianglemesh_t** out,
                                                            const o3d_trianglemesh_t* mesh,
                                                            int32_t number_of_iterations, double lambda_filter,
                                                            int32_t filter_scope) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::filter_smooth_laplacian(mesh_of(mesh), number_of_iterations, lambda_filter,
                                                                to_scope(filter_scope)));
    });
}

O3D_API o3d_status o3d_trianglemesh_filter_smooth_taubin(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                         int32_t number_of_iterations, double lambda_filter,
                                                         double mu, int32_t filter_scope) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::filter_smooth_taubin(mesh_of(mesh), number_of_iterations, lambda_filter, mu,
                                                             to_scope(filter_scope)));
    });
}

O3D_API o3d_status o3d_trianglemesh_subdivide_midpoint(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                       int32_t number_of_iterations) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::subdivide_midpoint(mesh_of(mesh), number_of_iterations));
    });
}

O3D_API o3d_status o3d_trianglemesh_subdivide_loop(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                   int32_t number_of_iterations) {
    return guard(__func__, [&] {
        require_out(out);
        return emit(out, o3d::geometry::subdivide_loop(mesh_of(mesh), number_of_iterations));
    });
}

O3D_API o3d_status o3d_trianglemesh_crop_aabb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                              const double min_bound[3], const double max_bound[3]) {
    return guard(__func__, [&] {
        require_out(out);
        const TriangleMesh& source = mesh_of(mesh);
        return emit(out, o3d::geometry::crop_aabb(source, vec3(min_bound, "min_bound"), vec3(max_bound, "max_bound")));
    });
}

}  // extern "C"

O3D_API o3d_status o3d_trianglemesh_deform_as_rigid_as_possible(o3d_trianglemesh_t** out,
                                                                const o3d_trianglemesh_t* mesh,
                                                                const int32_t* constraint_vertex_indices,
                                                                size_t num_indices,
                                                                const double* constraint_vertex_positions,
                                                                size_t num_positions, int32_t max_iter,
                                                                o3d_arap_energy energy, double smoothed_alpha) {
    return guard(__func__, [&] {
        require_out(out);
        if (num_indices != num_positions)
            throw o3d::InvalidArgument(std::to_string(num_indices) + " constraint indices but " +
                                       std::to_string(num_positions) + " positions");
        const size_t num_constraints = num_indices;
        if (num_constraints > 0) {
            require(constraint_vertex_indices, "constraint_vertex_indices");
            require(constraint_vertex_positions, "constraint_vertex_positions");
        }
        if (energy != O3D_ARAP_ENERGY_SPOKES && energy != O3D_ARAP_ENERGY_SMOOTHED)
            throw o3d::InvalidArgument("energy " + std::to_string(energy) +
                                       " is not O3D_ARAP_ENERGY_SPOKES or O3D_ARAP_ENERGY_SMOOTHED");
        std::vector<int> ids(constraint_vertex_indices, constraint_vertex_indices + num_constraints);
        std::vector<Eigen::Vector3d> positions(num_constraints);
        for (size_t i = 0; i < num_constraints; ++i)
            positions[i] = Eigen::Vector3d(constraint_vertex_positions[3 * i], constraint_vertex_positions[3 * i + 1],
                                           constraint_vertex_positions[3 * i + 2]);
        return emit(out, o3d::geometry::deform_as_rigid_as_possible(mesh_of(mesh), ids, positions, max_iter,
                                                                    static_cast<o3d::geometry::ArapEnergy>(energy),
                                                                    smoothed_alpha));
    });
}
