// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_cleanup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_compaction.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

uint64_t mix(uint64_t h) {  // splitmix64 finaliser: spreads nearby keys over the table
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    return h ^ (h >> 31);
}

uint64_t bits_of(double x) {
    x += 0.0;  // -0.0 becomes +0.0, so the two equal values hash alike
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

/// @brief For each of n items, the index of the first item equal to it (itself when none comes before),
/// by open addressing on `hash`. Deterministic: it only depends on the items' order.
template <typename Hash, typename Equal>
std::vector<int> first_equal(size_t n, Hash hash, Equal equal) {
    size_t capacity = 16;
    while (capacity < 2 * n) capacity <<= 1;
    const size_t mask = capacity - 1;
    std::vector<int> slots(capacity, -1);
    std::vector<int> first(n);
    for (size_t i = 0; i < n; ++i) {
        size_t s = mix(hash(i)) & mask;
        while (slots[s] >= 0 && !equal(static_cast<size_t>(slots[s]), i)) s = (s + 1) & mask;
        if (slots[s] < 0) slots[s] = static_cast<int>(i);
        first[i] = slots[s];
    }
    return first;
}

/// @brief Renumbering for keeping the first vertex of each class `representative[v]` (<= v).
void merge_into_representatives(TriangleMesh& mesh, const std::vector<int>& representative) {
    const size_t n = mesh.vertices.size();
    std::vector<uint8_t> keep(n);
    std::vector<int> new_index(n);
    int next = 0;
    for (size_t v = 0; v < n; ++v) {
        keep[v] = representative[v] == static_cast<int>(v);
        new_index[v] = keep[v] ? next++ : new_index[representative[v]];
    }
    if (static_cast<size_t>(next) == n) return;
    keep_vertices(mesh, keep, new_index);
}

/// @brief Cells of a uniform grid holding the finite vertices, for fixed-radius neighbour queries.
class VertexGrid {
public:
    VertexGrid(const std::vector<Eigen::Vector3d>& points, double cell) : cell_(cell) {
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
        for (const Eigen::Vector3d& p : points)
            if (p.allFinite()) lo = lo.cwiseMin(p);
        origin_ = lo;
        const size_t n = points.size();
        cell_of_.assign(n, -1);
        std::vector<Key> keys;
        size_t capacity = 16;
        while (capacity < 2 * n) capacity <<= 1;
        slots_.assign(capacity, -1);
        for (size_t i = 0; i < n; ++i) {
            if (!points[i].allFinite()) continue;
            const Key key = key_of(points[i]);
            int& slot = slot_of(key);
            if (slot < 0) {
                slot = static_cast<int>(keys_.size());
                keys_.push_back(key);
            }
            cell_of_[i] = slot;
        }
        // Members of each cell in CSR form, ascending by vertex index.
        offsets_.assign(keys_.size() + 1, 0);
        for (const int c : cell_of_)
            if (c >= 0) ++offsets_[c + 1];
        for (size_t c = 0; c < keys_.size(); ++c) offsets_[c + 1] += offsets_[c];
        members_.resize(offsets_.back());
        std::vector<int> fill(offsets_.begin(), offsets_.end() - 1);
        for (size_t i = 0; i < n; ++i)
            if (cell_of_[i] >= 0) members_[fill[cell_of_[i]]++] = static_cast<int>(i);
    }

    /// @brief Call f(j) for every finite vertex j in the 27 cells around p (p finite).
    template <typename F>
    void for_each_near(const Eigen::Vector3d& p, F f) const {
        const Key k = key_of(p);
        for (int64_t dx = -1; dx <= 1; ++dx)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dz = -1; dz <= 1; ++dz) {
                    const int c = find({k[0] + dx, k[1] + dy, k[2] + dz});
                    if (c < 0) continue;
                    for (int m = offsets_[c]; m < offsets_[c + 1]; ++m) f(members_[m]);
                }
    }

private:
    using Key = std::array<int64_t, 3>;

    Key key_of(const Eigen::Vector3d& p) const {
        Key k;
        for (int a = 0; a < 3; ++a) {
            // Clamped: with coordinates near DBL_MAX the offset can overflow to infinity (or NaN).
            const double q = std::floor((p(a) - origin_(a)) / cell_);
            k[a] = q >= 0 && q < 4e18 ? static_cast<int64_t>(q) : (q >= 4e18 ? int64_t(4e18) : 0);
        }
        return k;
    }
    size_t hash(const Key& k) const {
        return mix(static_cast<uint64_t>(k[0]) * 0x9E3779B97F4A7C15ULL ^ static_cast<uint64_t>(k[1]) * 0xC2B2AE3D27D4EB4FULL ^
                   static_cast<uint64_t>(k[2]) * 0x165667B19E3779F9ULL) &
               (slots_.size() - 1);
    }
    int& slot_of(const Key& k) {
        size_t s = hash(k);
        while (slots_[s] >= 0 && keys_[slots_[s]] != k) s = (s + 1) & (slots_.size() - 1);
        return slots_[s];
    }
    int find(const Key& k) const {
        size_t s = hash(k);
        while (slots_[s] >= 0) {
            if (keys_[slots_[s]] == k) return slots_[s];
            s = (s + 1) & (slots_.size() - 1);
        }
        return -1;
    }

    double cell_;
    Eigen::Vector3d origin_;
    std::vector<int> cell_of_, slots_, offsets_, members_;
    std::vector<Key> keys_;
};

}  // namespace

void remove_duplicated_vertices(TriangleMesh& mesh) {
    validate_triangles(mesh);
    const std::vector<Eigen::Vector3d>& v = mesh.vertices;
    const std::vector<int> first = first_equal(
        v.size(),
        [&](size_t i) -> uint64_t {
            // A NaN vertex equals nothing: hashing it by index keeps many of them from sharing one probe chain.
            if (v[i].array().isNaN().any()) return static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ULL;
            return bits_of(v[i](0)) ^ mix(bits_of(v[i](1)) + 0x9E3779B97F4A7C15ULL) ^ mix(mix(bits_of(v[i](2))));
        },
        [&](size_t i, size_t j) { return v[i](0) == v[j](0) && v[i](1) == v[j](1) && v[i](2) == v[j](2); });
    merge_into_representatives(mesh, first);
}

void remove_duplicated_triangles(TriangleMesh& mesh) {
    validate_triangles(mesh);
    const size_t m = mesh.triangles.size();
    std::vector<Eigen::Vector3i> sorted(m);
    for (size_t t = 0; t < m; ++t) {
        Eigen::Vector3i s = mesh.triangles[t];
        std::sort(s.data(), s.data() + 3);
        sorted[t] = s;
    }
    const std::vector<int> first = first_equal(
        m,
        [&](size_t t) {
            return (static_cast<uint64_t>(static_cast<uint32_t>(sorted[t](0))) << 32 |
                    static_cast<uint32_t>(sorted[t](1))) ^
                   mix(static_cast<uint32_t>(sorted[t](2)));
        },
        [&](size_t a, size_t b) { return sorted[a] == sorted[b]; });
    std::vector<uint8_t> keep(m);
    bool removed = false;
    for (size_t t = 0; t < m; ++t) {
        keep[t] = first[t] == static_cast<int>(t);
        removed = removed || !keep[t];
    }
    if (removed) keep_triangles(mesh, keep);
}

void remove_degenerate_triangles(TriangleMesh& mesh) {
    validate_triangles(mesh);
    const size_t m = mesh.triangles.size();
    std::vector<uint8_t> keep(m);
    bool removed = false;
    for (size_t t = 0; t < m; ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        keep[t] = tri(0) != tri(1) && tri(1) != tri(2) && tri(2) != tri(0);
        removed = removed || !keep[t];
    }
    if (removed) keep_triangles(mesh, keep);
}

void remove_unreferenced_vertices(TriangleMesh& mesh) {
    validate_triangles(mesh);
    const size_t n = mesh.vertices.size();
    std::vector<uint8_t> keep(n, 0);
    for (const Eigen::Vector3i& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) keep[tri(k)] = 1;
    std::vector<int> new_index(n, -1);
    int next = 0;
    for (size_t v = 0; v < n; ++v)
        if (keep[v]) new_index[v] = next++;
    if (static_cast<size_t>(next) == n) return;
    keep_vertices(mesh, keep, new_index);
}

void remove_non_manifold_edges(TriangleMesh& mesh) {
    const std::vector<double> areas = triangle_areas(mesh);  // validates
    const MeshEdges edges = mesh_edges(mesh);
    std::vector<uint8_t> keep(mesh.triangles.size(), 1);
    bool removed = false;
    // NaN areas sort first: a triangle with no finite area is the first to go.
    auto smaller = [&](int a, int b) {
        const double x = std::isnan(areas[a]) ? -1.0 : areas[a], y = std::isnan(areas[b]) ? -1.0 : areas[b];
        return x < y || (x == y && a < b);
    };
    std::vector<int> live;
    for (size_t e = 0; e < edges.size(); ++e) {
        if (edges.triangle_count(e) <= 2) continue;
        live.clear();
        for (int i = edges.triangle_offsets[e]; i < edges.triangle_offsets[e + 1]; ++i)
            if (keep[edges.triangles[i]]) live.push_back(edges.triangles[i]);
        if (live.size() <= 2) continue;
        std::sort(live.begin(), live.end(), smaller);
        for (size_t i = 0; i + 2 < live.size(); ++i) keep[live[i]] = 0;
        removed = true;
    }
    if (removed) keep_triangles(mesh, keep);
}

void merge_close_vertices(TriangleMesh& mesh, double eps) {
    if (!(eps >= 0.0) || !std::isfinite(eps))
        throw InvalidArgument("eps must be finite and >= 0, got " + std::to_string(eps));
    validate_triangles(mesh);
    const size_t n = mesh.vertices.size();
    const std::vector<Eigen::Vector3d>& v = mesh.vertices;
    const bool normals = mesh.has_vertex_normals(), colors = mesh.has_vertex_colors();

    // Open3D finds neighbours with a radius search, which keeps distances strictly below eps.
    std::vector<int> new_index(n, -1);
    std::vector<Eigen::Vector3d> out_vertices, out_normals, out_colors;
    if (eps > 0.0 && n > 0) {
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
        for (const Eigen::Vector3d& p : v)
            if (p.allFinite()) {
                lo = lo.cwiseMin(p);
                hi = hi.cwiseMax(p);
            }
        const double range = lo.allFinite() ? (hi - lo).maxCoeff() : 0.0;
        // Any cell >= eps finds every neighbour; the floor keeps cell coordinates far inside int64.
        const VertexGrid grid(v, std::max(eps, range * 1e-15));
        const double eps2 = eps * eps;
        std::vector<int> group;
        for (size_t i = 0; i < n; ++i) {
            if (new_index[i] >= 0) continue;
            const int id = static_cast<int>(out_vertices.size());
            new_index[i] = id;
            group.assign(1, static_cast<int>(i));
            if (v[i].allFinite())
                grid.for_each_near(v[i], [&](int j) {
                    if (new_index[j] < 0 && (v[j] - v[i]).squaredNorm() < eps2) group.push_back(j);
                });
            std::sort(group.begin() + 1, group.end());
            Eigen::Vector3d p = Eigen::Vector3d::Zero(), nrm = p, col = p;
            for (const int j : group) {
                new_index[j] = id;
                p += v[j];
                if (normals) nrm += mesh.vertex_normals[j];
                if (colors) col += mesh.vertex_colors[j];
            }
            const double count = static_cast<double>(group.size());
            out_vertices.push_back(p / count);
            if (normals) out_normals.push_back(nrm / count);
            if (colors) out_colors.push_back(col / count);
        }
    } else {
        for (size_t i = 0; i < n; ++i) new_index[i] = static_cast<int>(i);
        out_vertices = v;
        if (normals) out_normals = mesh.vertex_normals;
        if (colors) out_colors = mesh.vertex_colors;
    }
    mesh.vertices = std::move(out_vertices);
    mesh.vertex_normals = std::move(out_normals);
    mesh.vertex_colors = std::move(out_colors);
    for (Eigen::Vector3i& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) tri(k) = new_index[tri(k)];
    if (mesh.has_triangle_normals()) compute_triangle_normals(mesh, true);
}

}  // namespace o3d::geometry
