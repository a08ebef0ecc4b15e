// SPDX-License-Identifier: MIT
// C API: trianglemesh.h's surface reconstruction from point clouds (Poisson, ball pivoting, alpha shapes) and
// common.h's o3d_progress_options_init.
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/alpha_shape.h"
#include "o3d/geometry/ball_pivoting.h"
#include "o3d/geometry/poisson_reconstruction.h"
#include "o3d/tetramesh.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;

namespace {

// Open3D's create_from_point_cloud_poisson defaults.
constexpr o3d_poisson_options_t kPoissonDefaults = {sizeof(o3d_poisson_options_t), 8, 0.0, 1.1, 0, 0, nullptr, nullptr};
constexpr o3d_progress_options_t kProgressDefaults = {sizeof(o3d_progress_options_t), 0, nullptr, nullptr};

template <typename Handle>
Handle** require_out(Handle** out, const char* name) {
    require(out, name);
    *out = nullptr;
    return out;
}

void give_mesh(o3d_trianglemesh_t** out, o3d::geometry::TriangleMesh mesh) {
    auto handle = std::make_unique<o3d_trianglemesh>();
    handle->mesh = std::move(mesh);
    *out = handle.release();
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_progress_options_init(o3d_progress_options_t* opts, uint32_t struct_size) {
    return guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kProgressDefaults, "opts"); });
}

O3D_API o3d_status o3d_poisson_options_init(o3d_poisson_options_t* opts, uint32_t struct_size) {
    return guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kPoissonDefaults, "opts"); });
}

O3D_API o3d_status o3d_trianglemesh_create_from_point_cloud_poisson(o3d_trianglemesh_t** out_mesh,
                                                                   o3d_feature_t** out_densities,
                                                                   const o3d_pointcloud_t* pc,
                                                                   const o3d_poisson_options_t* opts) {
    return guard(__func__, [&] {
        require_out(out_mesh, "out_mesh");
        require_out(out_densities, "out_densities");
        const auto& cloud = require(pc, "pc")->cloud;
        const o3d_poisson_options_t o = o3d::capi::read_options(opts, kPoissonDefaults, "opts");
        o3d::geometry::PoissonOptions options;
        options.depth = o.depth;
        options.width = o.width;
        options.scale = o.scale;
        options.linear_fit = o.linear_fit != 0;
        options.num_threads = o3d::capi::to_num_threads(o.num_threads);
        options.progress = o3d::capi::to_progress(o.progress, o.user_data);
        auto result = o3d::geometry::create_from_point_cloud_poisson(cloud, options);
        auto densities = std::make_unique<o3d_feature>();
        densities->feature.data =
            Eigen::Map<const Eigen::MatrixXd>(result.densities.data(), 1, (Eigen::Index)result.densities.size());
        auto mesh = std::make_unique<o3d_trianglemesh>();
        mesh->mesh = std::move(result.mesh);
        *out_mesh = mesh.release();
        *out_densities = densities.release();
    });
}

O3D_API o3d_status o3d_trianglemesh_create_from_point_cloud_ball_pivoting(o3d_trianglemesh_t** out,
                                                                         const o3d_pointcloud_t* pc,
                                                                         const double* radii, size_t num_radii,
                                                                         const o3d_progress_options_t* opts) {
    return guard(__func__, [&] {
        require_out(out, "out");
        const auto& cloud = require(pc, "pc")->cloud;
        if (num_radii > 0) require(radii, "radii");
        const o3d_progress_options_t o = o3d::capi::read_options(opts, kProgressDefaults, "opts");
        o3d::capi::to_num_threads(o.num_threads);
        give_mesh(out, o3d::geometry::create_from_point_cloud_ball_pivoting(
                           cloud, std::vector<double>(radii, radii + num_radii),
                           o3d::capi::to_progress(o.progress, o.user_data)));
    });
}

O3D_API o3d_status o3d_trianglemesh_create_from_point_cloud_alpha_shape(o3d_trianglemesh_t** out,
                                                                       const o3d_pointcloud_t* pc, double alpha,
                                                                       const o3d_tetramesh_t* tetramesh,
                                                                       const int32_t* point_map,
                                                                       size_t num_point_map,
                                                                       const o3d_progress_options_t* opts) {
    return guard(__func__, [&] {
        require_out(out, "out");
        const auto& cloud = require(pc, "pc")->cloud;
        const o3d_progress_options_t o = o3d::capi::read_options(opts, kProgressDefaults, "opts");
        const int threads = o3d::capi::to_num_threads(o.num_threads);
        const auto progress = o3d::capi::to_progress(o.progress, o.user_data);
        if (progress && !progress(0.0)) throw o3d::Cancelled("cancelled by the progress callback");
        if (!tetramesh) {
            give_mesh(out, o3d::geometry::create_from_point_cloud_alpha_shape(cloud, alpha, nullptr, nullptr, threads));
        } else {
            if (num_point_map > 0) require(point_map, "point_map");
            const auto& tetras = tetramesh->mesh;
            if (num_point_map != tetras.vertices.size())
                throw o3d::InvalidArgument("point_map has " + std::to_string(num_point_map) +
                                           " entries but the tetra mesh has " +
                                           std::to_string(tetras.vertices.size()) + " vertices");
            std::vector<size_t> map(num_point_map);
            for (size_t i = 0; i < num_point_map; ++i) {
                if (point_map[i] < 0 || static_cast<size_t>(point_map[i]) >= cloud.points.size())
                    throw o3d::InvalidArgument("point_map[" + std::to_string(i) + "] = " +
                                               std::to_string(point_map[i]) + " is not a point of pc");
                map[i] = static_cast<size_t>(point_map[i]);
            }
            give_mesh(out, o3d::geometry::create_from_point_cloud_alpha_shape(cloud, alpha, &tetras, &map, threads));
        }
        if (progress && !progress(1.0)) {
            o3d_trianglemesh_destroy(*out);
            *out = nullptr;
            throw o3d::Cancelled("cancelled by the progress callback");
        }
    });
}

}  // extern "C"
