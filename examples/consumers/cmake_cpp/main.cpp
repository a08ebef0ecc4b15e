// A C++ program built against an installed o3d through find_package(o3d) -> o3d::o3dpp (header-only wrapper).
#include <o3dpp/o3dpp.hpp>

#include <cstdio>
#include <vector>

int main() {
    std::vector<o3dpp::Vec3> grid;  // a 10 x 10 x 10 grid with spacing 1
    for (int i = 0; i < 1000; ++i) grid.push_back({double(i % 10), double((i / 10) % 10), double(i / 100)});
    const o3dpp::PointCloud cloud(grid);
    const o3dpp::PointCloud down = cloud.voxel_down_sample(2.0);
    std::printf("o3dpp: %zu points -> %zu after voxel_down_sample(2)\n", cloud.size(), down.size());
    try {
        cloud.voxel_down_sample(-1.0);  // bad input is an exception, not a crash
        return 1;
    } catch (const o3dpp::Error& e) {
        std::printf("error as expected: %s\n", e.what());
    }
    // As Open3D, voxels start half a voxel below the minimum: 0 | 1 2 | ... | 9 gives 6 per axis.
    return down.size() == 216 ? 0 : 1;
}
