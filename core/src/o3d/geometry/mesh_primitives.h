// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_primitives.h
/// @brief Open3D's TriangleMesh.create_* factories: the same vertex and triangle counts, order and winding
/// (outward normals), so indices and fingerprints match Open3D 0.20. Bad arguments (a size <= 0, NaN or
/// infinite; a resolution or split < 1; a sphere resolution < 2; more vertices than int32 indices reach)
/// throw o3d::InvalidArgument.
#include <Eigen/Core>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Box [0,w] x [0,h] x [0,d]: 8 vertices, 12 triangles.
TriangleMesh create_box(double width = 1.0, double height = 1.0, double depth = 1.0);
/// @brief UV sphere about the origin: poles, then resolution - 1 rings of 2 * resolution vertices.
TriangleMesh create_sphere(double radius = 1.0, int resolution = 20);
/// @brief Cylinder along z from -height/2 to height/2: cap centres, then split + 1 rings top to bottom.
TriangleMesh create_cylinder(double radius = 1.0, double height = 2.0, int resolution = 20, int split = 4);
/// @brief Cone along z, base at z = 0, apex at z = height: base centre, apex, then `split` shrinking rings.
TriangleMesh create_cone(double radius = 1.0, double height = 2.0, int resolution = 20, int split = 1);
/// @brief Torus about z: radial_resolution tube circles of tubular_resolution vertices.
TriangleMesh create_torus(double torus_radius = 1.0, double tube_radius = 0.5, int radial_resolution = 30,
                          int tubular_resolution = 20);
/// @brief A cylinder on [0, cylinder_height] then a cone on top of it, along z.
TriangleMesh create_arrow(double cylinder_radius = 1.0, double cone_radius = 1.5, double cylinder_height = 5.0,
                          double cone_height = 4.0, int resolution = 20, int cylinder_split = 4, int cone_split = 1);
/// @brief A grey sphere at `origin` and red x, green y, blue z arrows of length `size`, with vertex normals.
TriangleMesh create_coordinate_frame(double size = 1.0, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());
/// @brief A band of `width` around a circle of `radius` in the xy-plane, turned by twists * 180 degrees
/// along its length: length_split columns of width_split vertices. An odd number of twists gives a
/// Moebius strip (one side, non-orientable), an even number an orientable band. z is multiplied by
/// `flatness`, everything by `scale`.
TriangleMesh create_mobius(int length_split = 70, int width_split = 15, int twists = 1, double radius = 1.0,
                           double flatness = 1.0, double width = 1.0, double scale = 1.0);
/// @brief Regular solids with their vertices at distance `radius` from the origin.
TriangleMesh create_tetrahedron(double radius = 1.0);
TriangleMesh create_octahedron(double radius = 1.0);
TriangleMesh create_icosahedron(double radius = 1.0);

}  // namespace o3d::geometry
