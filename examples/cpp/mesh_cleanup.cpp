// SPDX-License-Identifier: MIT
// Mesh clean-up through the C++ wrapper (o3dpp): read a mesh, merge duplicated vertices, drop
// degenerate / duplicated triangles and unreferenced vertices, recompute normals, then sample points
// uniformly on the surface and write them.
// Usage: mesh_cleanup <input mesh> <output cloud> [number_of_points (default 10000)]
#include <cstdlib>
#include <iostream>

#include "o3dpp/o3dpp.hpp"

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::cerr << "usage: " << argv[0] << " <input mesh> <output cloud> [number_of_points]\n";
        return 2;
    }
    const long requested = argc == 4 ? std::strtol(argv[3], nullptr, 10) : 10000;
    if (requested <= 0) {
        std::cerr << "mesh_cleanup: number_of_points must be a positive integer\n";
        return 2;
    }
    try {
        auto mesh = o3dpp::read_triangle_mesh(argv[1]);
        std::cout << "read " << mesh.num_vertices() << " vertices, " << mesh.num_triangles() << " triangles from "
                  << argv[1] << "\n";
        mesh.remove_duplicated_vertices()
            .remove_degenerate_triangles()
            .remove_duplicated_triangles()
            .remove_unreferenced_vertices()
            .compute_vertex_normals();
        std::cout << "cleaned: " << mesh.num_vertices() << " vertices, " << mesh.num_triangles()
                  << " triangles, area " << mesh.get_surface_area() << ", edge-manifold "
                  << (mesh.is_edge_manifold() ? "yes" : "no") << ", watertight " << (mesh.is_watertight() ? "yes" : "no")
                  << "\n";
        const auto cloud = mesh.sample_points_uniformly(static_cast<std::size_t>(requested));
        o3dpp::write_point_cloud(argv[2], cloud);
        std::cout << "wrote " << cloud.size() << " sampled points with normals to " << argv[2] << "\n";
        return cloud.size() == static_cast<std::size_t>(requested) && cloud.has_normals() ? 0 : 1;
    } catch (const o3dpp::Error& e) {
        std::cerr << "mesh_cleanup: " << e.code_name() << ": " << e.what() << "\n";
        return 1;
    }
}
