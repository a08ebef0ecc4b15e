// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_sampling.h"

#include <Eigen/Geometry>  // cross(), used by triangle_cross
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// @brief splitmix64's output function: a bijective mix good enough to turn a counter into random bits.
inline uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

constexpr uint64_t kGolden = 0x9E3779B97F4A7C15ULL;

/// @brief Uniform double in [0, 1) from 53 random bits.
inline double unit_double(uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

/// @brief Linear RGB of texel (u, v) by nearest lookup, as Open3D samples textures; black when the
/// image format is not one it can read.
Eigen::Vector3d texel_color(const Image& image, const Eigen::Vector2d& uv) {
    if (image.empty() || image.byte_size() != image.data.size()) return Eigen::Vector3d::Zero();
    auto clamp_index = [](double x, int size) {
        const double i = std::floor(x * size);
        if (!(i >= 0)) return 0;  // also NaN
        return i >= size - 1 ? size - 1 : static_cast<int>(i);
    };
    const int col = clamp_index(uv(0), image.width), row = clamp_index(uv(1), image.height);
    auto channel = [&](int c) -> double {
        const int ch = std::min(c, image.num_channels - 1);
        switch (image.bytes_per_channel) {
            case 1: return image.pixel<uint8_t>(col, row)[ch] / 255.0;
            case 2: return image.pixel<uint16_t>(col, row)[ch] / 65535.0;
            case 4: return static_cast<double>(image.pixel<float>(col, row)[ch]);
            default: return 0.0;
        }
    };
    if (image.num_channels < 1) return Eigen::Vector3d::Zero();
    return Eigen::Vector3d(channel(0), channel(1), channel(2));
}

/// @brief Walker's alias table (Vose's construction): O(1) draws of index t with probability area[t] / total,
/// where a binary search of the area CDF would miss the cache on every level for large meshes.
class AliasTable {
public:
    AliasTable(const std::vector<double>& area, double total) : keep_(area.size(), 1.0), alias_(area.size()) {
        const size_t n = area.size();
        std::vector<double> scaled(n);
        std::vector<size_t> small, large;
        for (size_t t = 0; t < n; ++t) {
            alias_[t] = t;
            scaled[t] = area[t] / total * static_cast<double>(n);
            (scaled[t] < 1 ? small : large).push_back(t);
        }
        while (!small.empty() && !large.empty()) {
            const size_t l = small.back(), g = large.back();
            small.pop_back();
            keep_[l] = scaled[l];
            alias_[l] = g;
            scaled[g] = (scaled[g] + scaled[l]) - 1;
            if (scaled[g] < 1) {
                large.pop_back();
                small.push_back(g);
            }
        }
        // What is left has probability 1 up to rounding: keep_ stays 1.
    }
    /// @brief Slot from 64 random bits, then the slot or its alias by the coin in [0, 1).
    size_t pick(uint64_t bits, double coin) const {
        const size_t slot = static_cast<size_t>((static_cast<unsigned __int128>(bits) * keep_.size()) >> 64);
        return coin < keep_[slot] ? slot : alias_[slot];
    }

private:
    std::vector<double> keep_;
    std::vector<size_t> alias_;
};

}  // namespace

PointCloud sample_points_uniformly(const TriangleMesh& mesh, size_t number_of_points, bool use_triangle_normal,
                                   uint64_t seed, int num_threads) {
    validate_triangles(mesh);
    if (number_of_points == 0) throw InvalidArgument("number_of_points must be > 0");
    if (mesh.triangles.empty()) throw InvalidArgument("the mesh has no triangles");
    const size_t nt = mesh.triangles.size();
    const int threads = utility::resolve_num_threads(num_threads);

    std::vector<double> area(nt);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t t = 0; t < static_cast<int64_t>(nt); ++t)
        area[static_cast<size_t>(t)] = triangle_area(mesh, static_cast<size_t>(t));
    double total = 0;
    for (double a : area) total += a;
    if (!(total > 0) || !std::isfinite(total))
        throw InvalidArgument("the surface area is " + std::to_string(total) + "; it must be finite and > 0");
    const AliasTable table(area, total);

    const bool tex = mesh.has_triangle_uvs() && mesh.has_textures();
    const bool vertex_colors = !tex && mesh.has_vertex_colors();
    const bool vertex_normals = !use_triangle_normal && mesh.has_vertex_normals();
    const bool given_triangle_normals = mesh.has_triangle_normals();
    const bool material_ids = mesh.has_triangle_material_ids();

    PointCloud cloud;
    cloud.points.resize(number_of_points);
    if (use_triangle_normal || vertex_normals) cloud.normals.resize(number_of_points);
    if (tex || vertex_colors) cloud.colors.resize(number_of_points);
    const uint64_t stream = mix64(seed + kGolden);

#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t pi = 0; pi < static_cast<int64_t>(number_of_points); ++pi) {
        const size_t i = static_cast<size_t>(pi);
        // Four draws per point from its own counter: the cloud depends on the seed only, not on threads.
        const uint64_t base = stream + 4 * i * kGolden;
        const size_t t = table.pick(mix64(base + kGolden), unit_double(mix64(base + 2 * kGolden)));
        const double r1 = unit_double(mix64(base + 3 * kGolden));
        const double r2 = unit_double(mix64(base + 4 * kGolden));
        const double s = std::sqrt(r1);
        const double a = 1 - s, b = s * (1 - r2), c = s * r2;
        const Eigen::Vector3i& tri = mesh.triangles[t];
        cloud.points[i] = a * mesh.vertices[tri(0)] + b * mesh.vertices[tri(1)] + c * mesh.vertices[tri(2)];
        if (use_triangle_normal) {
            cloud.normals[i] = given_triangle_normals ? mesh.triangle_normals[t] : triangle_cross(mesh, t).normalized();
        } else if (vertex_normals) {
            cloud.normals[i] = a * mesh.vertex_normals[tri(0)] + b * mesh.vertex_normals[tri(1)] +
                               c * mesh.vertex_normals[tri(2)];
        }
        if (tex) {
            const int id = material_ids ? mesh.triangle_material_ids[t] : 0;
            const Eigen::Vector2d uv =
                a * mesh.triangle_uvs[3 * t] + b * mesh.triangle_uvs[3 * t + 1] + c * mesh.triangle_uvs[3 * t + 2];
            cloud.colors[i] = id >= 0 && static_cast<size_t>(id) < mesh.textures.size()
                                  ? texel_color(mesh.textures[static_cast<size_t>(id)], uv)
                                  : Eigen::Vector3d::Zero();
        } else if (vertex_colors) {
            cloud.colors[i] =
                a * mesh.vertex_colors[tri(0)] + b * mesh.vertex_colors[tri(1)] + c * mesh.vertex_colors[tri(2)];
        }
    }
    return cloud;
}

}  // namespace o3d::geometry
