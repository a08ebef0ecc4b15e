// SPDX-License-Identifier: MIT
// Figure 1 through the C++ wrapper (o3dpp): read, voxel down-sample (0.05), estimate normals
// (hybrid 0.1 / 30), write. Errors arrive as o3dpp::Error with the status and the library's message.
// Usage: figure1_cpp <input> <output>
#include <iostream>

#include "o3dpp/o3dpp.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: " << argv[0] << " <input> <output>\n";
        return 2;
    }
    try {
        std::cout << "o3d " << o3dpp::version() << "\n";
        const auto cloud = o3dpp::read_point_cloud(argv[1]);
        std::cout << "read " << cloud.size() << " points from " << argv[1] << "\n";
        auto down = cloud.voxel_down_sample(0.05);
        std::cout << "voxel_down_sample(0.05): " << cloud.size() << " -> " << down.size() << " points\n";
        down.estimate_normals(o3dpp::SearchParam::Hybrid(0.1, 30));
        std::cout << "estimate_normals(hybrid radius=0.1 max_nn=30): normals " << (down.has_normals() ? "yes" : "no")
                  << "\n";
        o3dpp::write_point_cloud(argv[2], down);
        std::cout << "wrote " << down.size() << " points with normals to " << argv[2] << "\n";
        return down.has_normals() && !down.empty() ? 0 : 1;
    } catch (const o3dpp::Error& e) {
        std::cerr << "figure1_cpp: " << e.code_name() << ": " << e.what() << "\n";
        return 1;
    }
}
