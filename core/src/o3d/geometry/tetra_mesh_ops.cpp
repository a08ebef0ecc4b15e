// SPDX-License-Identifier: MIT
#include "o3d/geometry/tetra_mesh_ops.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// Keep the tetras for which `keep(t)` holds, in order.
template <class Keep>
void filter_tetras(TetraMesh& mesh, Keep keep) {
    size_t out = 0;
    for (size_t t = 0; t < mesh.tetras.size(); ++t)
        if (keep(mesh.tetras[t])) mesh.tetras[out++] = mesh.tetras[t];
    mesh.tetras.resize(out);
}

/// Renumber the vertices through `new_index` (-1 = dropped; kept ones keep their relative order).
void compact_vertices(TetraMesh& mesh, const std::vector<int>& new_index) {
    size_t out = 0;
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (new_index[v] >= 0) mesh.vertices[out++] = mesh.vertices[v];
    mesh.vertices.resize(out);
}

}  // namespace

void validate_tetras(const TetraMesh& mesh) {
    const size_t n = mesh.vertices.size();
    for (size_t t = 0; t < mesh.tetras.size(); ++t)
        for (int k = 0; k < 4; ++k) {
            const int i = mesh.tetras[t](k);
            if (i < 0 || static_cast<size_t>(i) >= n)
                throw InvalidArgument("tetra " + std::to_string(t) + " has vertex index " + std::to_string(i) +
                                      " outside [0, " + std::to_string(n) + ")");
        }
}

void remove_duplicated_vertices(TetraMesh& mesh) {
    validate_tetras(mesh);
    // 0.0 + x turns -0.0 into +0.0 so that the two are one key; a vertex with a NaN never merges.
    std::map<std::array<double, 3>, int> first;
    std::vector<int> new_index(mesh.vertices.size());
    std::vector<Eigen::Vector3d> kept;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const Eigen::Vector3d& p = mesh.vertices[v];
        const int next = static_cast<int>(kept.size());
        bool is_new = true;
        if (!p.hasNaN()) {
            auto inserted = first.emplace(std::array<double, 3>{0.0 + p.x(), 0.0 + p.y(), 0.0 + p.z()}, next);
            is_new = inserted.second;
            new_index[v] = inserted.first->second;
        }
        if (is_new) {
            new_index[v] = next;
            kept.push_back(p);
        }
    }
    mesh.vertices.swap(kept);
    for (Eigen::Vector4i& t : mesh.tetras)
        for (int k = 0; k < 4; ++k) t(k) = new_index[static_cast<size_t>(t(k))];
}

void remove_duplicated_tetras(TetraMesh& mesh) {
    validate_tetras(mesh);
    std::set<std::array<int, 4>> seen;
    filter_tetras(mesh, [&](const Eigen::Vector4i& t) {
        std::array<int, 4> key{t(0), t(1), t(2), t(3)};
        std::sort(key.begin(), key.end());
        return seen.insert(key).second;
    });
}

void remove_unreferenced_vertices(TetraMesh& mesh) {
    validate_tetras(mesh);
    std::vector<int> new_index(mesh.vertices.size(), -1);
    for (const Eigen::Vector4i& t : mesh.tetras)
        for (int k = 0; k < 4; ++k) new_index[static_cast<size_t>(t(k))] = 0;
    int next = 0;
    for (int& i : new_index)
        if (i == 0) i = next++;
    compact_vertices(mesh, new_index);
    for (Eigen::Vector4i& t : mesh.tetras)
        for (int k = 0; k < 4; ++k) t(k) = new_index[static_cast<size_t>(t(k))];
}

void remove_degenerate_tetras(TetraMesh& mesh) {
    validate_tetras(mesh);
    filter_tetras(mesh, [](const Eigen::Vector4i& t) {
        return t(0) != t(1) && t(0) != t(2) && t(0) != t(3) && t(1) != t(2) && t(1) != t(3) && t(2) != t(3);
    });
}

Eigen::Vector3d get_min_bound(const TetraMesh& mesh) {
    if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d lo = mesh.vertices[0];
    for (const Eigen::Vector3d& p : mesh.vertices) lo = lo.cwiseMin(p);
    return lo;
}

Eigen::Vector3d get_max_bound(const TetraMesh& mesh) {
    if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d hi = mesh.vertices[0];
    for (const Eigen::Vector3d& p : mesh.vertices) hi = hi.cwiseMax(p);
    return hi;
}

Eigen::Vector3d get_center(const TetraMesh& mesh) {
    if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : mesh.vertices) sum += p;
    return sum / static_cast<double>(mesh.vertices.size());
}

}  // namespace o3d::geometry
