// SPDX-License-Identifier: MIT
// C API: the primitives of trianglemesh.h, a thin layer over core/src/o3d/geometry/mesh_primitives.h.
#include <memory>
#include <utility>

#include "internal.h"
#include "o3d/geometry/mesh_primitives.h"
#include "o3d/o3d.h"

namespace {

/// @brief Run `make` under the guard and hand its mesh out as a new handle (*out stays NULL on failure).
template <typename Make>
o3d_status create(const char* function, o3d_trianglemesh_t** out, Make&& make) {
    return o3d::capi::guard(function, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        auto mesh = std::make_unique<o3d_trianglemesh>();
        mesh->mesh = make();
        *out = mesh.release();
    });
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_trianglemesh_create_box(o3d_trianglemesh_t** out, double width, double height, double depth) {
    return create(__func__, out, [&] { return o3d::geometry::create_box(width, height, depth); });
}

O3D_API o3d_status o3d_trianglemesh_create_sphere(o3d_trianglemesh_t** out, double radius, int32_t resolution) {
    return create(__func__, out, [&] { return o3d::geometry::create_sphere(radius, resolution); });
}

O3D_API o3d_status o3d_trianglemesh_create_cylinder(o3d_trianglemesh_t** out, double radius, double height,
                                                    int32_t resolution, int32_t split) {
    return create(__func__, out, [&] { return o3d::geometry::create_cylinder(radius, height, resolution, split); });
}

O3D_API o3d_status o3d_trianglemesh_create_cone(o3d_trianglemesh_t** out, double radius, double height,
                                                int32_t resolution, int32_t split) {
    return create(__func__, out, [&] { return o3d::geometry::create_cone(radius, height, resolution, split); });
}

O3D_API o3d_status o3d_trianglemesh_create_torus(o3d_trianglemesh_t** out, double torus_radius, double tube_radius,
                                                 int32_t radial_resolution, int32_t tubular_resolution) {
    return create(__func__, out, [&] {
        return o3d::geometry::create_torus(torus_radius, tube_radius, radial_resolution, tubular_resolution);
    });
}

O3D_API o3d_status o3d_trianglemesh_create_arrow(o3d_trianglemesh_t** out, double cylinder_radius, double cone_radius,
                                                 double cylinder_height, double cone_height, int32_t resolution,
                                                 int32_t cylinder_split, int32_t cone_split) {
    return create(__func__, out, [&] {
        return o3d::geometry::create_arrow(cylinder_radius, cone_radius, cylinder_height, cone_height, resolution,
                                           cylinder_split, cone_split);
    });
}

O3D_API o3d_status o3d_trianglemesh_create_coordinate_frame(o3d_trianglemesh_t** out, double size,
                                                            const double origin[3]) {
    return create(__func__, out, [&] {
        const Eigen::Vector3d o = origin ? Eigen::Vector3d(origin[0], origin[1], origin[2]) : Eigen::Vector3d::Zero();
        return o3d::geometry::create_coordinate_frame(size, o);
    });
}

O3D_API o3d_status o3d_trianglemesh_create_tetrahedron(o3d_trianglemesh_t** out, double radius) {
    return create(__func__, out, [&] { return o3d::geometry::create_tetrahedron(radius); });
}

O3D_API o3d_status o3d_trianglemesh_create_octahedron(o3d_trianglemesh_t** out, double radius) {
    return create(__func__, out, [&] { return o3d::geometry::create_octahedron(radius); });
}

O3D_API o3d_status o3d_trianglemesh_create_icosahedron(o3d_trianglemesh_t** out, double radius) {
    return create(__func__, out, [&] { return o3d::geometry::create_icosahedron(radius); });
}

namespace {
const o3d_mobius_options_t kMobiusDefaults{sizeof(o3d_mobius_options_t), 70, 15, 1, 1.0, 1.0, 1.0, 1.0};
}  // namespace

O3D_API o3d_status o3d_mobius_options_init(o3d_mobius_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kMobiusDefaults, "opts"); });
}

O3D_API o3d_status o3d_trianglemesh_create_mobius(o3d_trianglemesh_t** out, const o3d_mobius_options_t* opts) {
    return create(__func__, out, [&] {
        const o3d_mobius_options_t o = o3d::capi::read_options(opts, kMobiusDefaults, "opts");
        return o3d::geometry::create_mobius(o.length_split, o.width_split, o.twists, o.radius, o.flatness, o.width,
                                            o.scale);
    });
}

}  // extern "C"
