// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_simplify_quadric.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/error_quadric.h"
#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_normals_util.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// @brief Where and at what cost edge (a, b), a < b, collapses.
struct Collapse {
    double cost;
    Eigen::Vector3d target;
};

/// @brief A queued edge, valid while neither endpoint has changed since it was queued (`time` is not older
/// than either endpoint's last change): stale entries are skipped when popped instead of being searched for.
struct QueuedEdge {
    int a, b;
    uint32_t time;
};

/// @brief Heap entries stay small (the heap's sifting dominates the run time); ties pop in queue order.
struct HeapEntry {
    double cost;
    uint32_t ref;  ///< index into the queued edges
};

struct CostlierFirst {
    bool operator()(const HeapEntry& x, const HeapEntry& y) const {
        return x.cost > y.cost || (x.cost == y.cost && x.ref > y.ref);
    }
};

inline bool has_vertex(const Eigen::Vector3i& t, int v) { return t(0) == v || t(1) == v || t(2) == v; }

class Decimator {
public:
    Decimator(const TriangleMesh& mesh, double boundary_weight)
        : vertices_(mesh.vertices), triangles_(mesh.triangles) {
        const size_t nv = vertices_.size(), nt = triangles_.size();
        if (mesh.has_vertex_normals()) normals_ = mesh.vertex_normals;
        if (mesh.has_vertex_colors()) colors_ = mesh.vertex_colors;
        vertex_alive_.assign(nv, 1);
        triangle_alive_.assign(nt, 1);
        changed_.assign(nv, 0);
        mark_.assign(nv, 0);
        boundary_.assign(nv, 0);
        quadrics_.resize(nv);
        around_.resize(nv);

        std::vector<double> area(nt, 0.0);
        for (size_t t = 0; t < nt; ++t) {
            const Eigen::Vector3i& tri = triangles_[t];
            if (tri(0) == tri(1) || tri(1) == tri(2) || tri(2) == tri(0)) {
                triangle_alive_[t] = 0;  // no area, no edge of its own: it only gets in the way
                continue;
            }
            ++live_triangles_;
            for (int k = 0; k < 3; ++k) around_[tri(k)].push_back(static_cast<int>(t));
            Eigen::Vector3d n;
            double d;
            area[t] = triangle_area(mesh, t);
            if (triangle_plane(vertices_[tri(0)], vertices_[tri(1)], vertices_[tri(2)], n, d)) {
                const ErrorQuadric q = ErrorQuadric::plane(n, d, area[t]);
                for (int k = 0; k < 3; ++k) quadrics_[tri(k)] += q;
            }
        }

        // Boundary edges: the plane holding the edge, perpendicular to its triangle, keeps the border in place.
        const MeshEdges edges = mesh_edges(mesh);
        for (size_t s = 0; s < edges.side_edge.size(); ++s) {
            const size_t t = s / 3;
            if (!triangle_alive_[t] || edges.triangle_count(static_cast<size_t>(edges.side_edge[s])) != 1) continue;
            const Eigen::Vector3i& tri = triangles_[t];
            const int k = static_cast<int>(s % 3);
            const int v0 = tri(k), v1 = tri((k + 1) % 3);
            boundary_[v0] = boundary_[v1] = 1;
            const Eigen::Vector3d face = triangle_cross(mesh, t);
            const Eigen::Vector3d normal = (vertices_[v1] - vertices_[v0]).cross(face);
            const double len = normal.norm();
            if (!(len > 0) || boundary_weight == 0) continue;
            const Eigen::Vector3d unit = normal / len;
            const ErrorQuadric q = ErrorQuadric::plane(unit, -unit.dot(vertices_[v0]), area[t] * boundary_weight);
            quadrics_[v0] += q;
            quadrics_[v1] += q;
        }
        for (const Eigen::Vector2i& e : edges.endpoints)
            if (e(0) != e(1)) edge_list_.push_back(e);
    }

    void run(size_t target, double maximum_error) {
        size_t collapses_since_fill = 1;
        while (live_triangles_ > target) {
            if (heap_.empty()) {
                // Skipped collapses may have become legal since: look at every live edge once more, and stop
                // only when a full pass changed nothing.
                if (collapses_since_fill == 0) break;
                fill_heap();
                collapses_since_fill = 0;
                if (heap_.empty()) break;
            }
            std::pop_heap(heap_.begin(), heap_.end(), CostlierFirst());
            const HeapEntry top = heap_.back();
            heap_.pop_back();
            const QueuedEdge e = queued_[top.ref];
            if (!vertex_alive_[e.a] || !vertex_alive_[e.b] || changed_[e.a] > e.time || changed_[e.b] > e.time)
                continue;
            if (top.cost > maximum_error) break;
            const Collapse c = evaluate(e.a, e.b);  // as when queued: neither end has changed since
            if (!allowed(e.a, e.b, c.target)) continue;
            collapse(e.a, e.b, c.target);
            ++collapses_since_fill;
        }
    }

    TriangleMesh result(const TriangleMesh& input) const {
        TriangleMesh out;
        const size_t nv = vertices_.size();
        std::vector<int> index(nv, -1);
        for (size_t v = 0; v < nv; ++v) {
            if (!vertex_alive_[v]) continue;
            index[v] = static_cast<int>(out.vertices.size());
            out.vertices.push_back(vertices_[v]);
            if (!normals_.empty()) out.vertex_normals.push_back(normals_[v]);
            if (!colors_.empty()) out.vertex_colors.push_back(colors_[v]);
        }
        const bool material_ids = input.has_triangle_material_ids();
        for (size_t t = 0; t < triangles_.size(); ++t) {
            if (!triangle_alive_[t]) continue;
            const Eigen::Vector3i& tri = triangles_[t];
            out.triangles.emplace_back(index[tri(0)], index[tri(1)], index[tri(2)]);
            if (material_ids) out.triangle_material_ids.push_back(input.triangle_material_ids[t]);
        }
        if (material_ids) out.textures = input.textures;
        if (input.has_triangle_normals()) out.triangle_normals = unit_triangle_normals(out);
        return out;
    }

private:
    void fill_heap() {
        heap_.clear();
        queued_.clear();
        if (edge_list_.empty()) {
            // After the first pass: the live edges, each once.
            for (size_t v = 0; v < vertices_.size(); ++v) {
                if (!vertex_alive_[v]) continue;
                const int a = static_cast<int>(v);
                for (int t : around_[v]) {
                    if (!triangle_alive_[t]) continue;
                    for (int k = 0; k < 3; ++k) {
                        const int b = triangles_[t](k);
                        if (b > a && mark_[b] != round_ + 1) {
                            mark_[b] = round_ + 1;
                            enqueue(a, b);
                        }
                    }
                }
                round_ += 2;
            }
        } else {
            heap_.reserve(2 * edge_list_.size());
            queued_.reserve(3 * edge_list_.size());
            for (const Eigen::Vector2i& e : edge_list_) enqueue(e(0), e(1));
            edge_list_.clear();
            edge_list_.shrink_to_fit();
        }
        std::make_heap(heap_.begin(), heap_.end(), CostlierFirst());
    }

    /// @brief Queue edge (v0, v1) at its current cost (the heap is left for the caller to order).
    void enqueue(int v0, int v1) {
        const int a = std::min(v0, v1), b = std::max(v0, v1);
        heap_.push_back(HeapEntry{evaluate(a, b).cost, static_cast<uint32_t>(queued_.size())});
        queued_.push_back(QueuedEdge{a, b, clock_});
    }

    Collapse evaluate(int a, int b) const {
        Collapse c;
        const ErrorQuadric q = quadrics_[a] + quadrics_[b];
        const Eigen::Vector3d& pa = vertices_[a];
        const Eigen::Vector3d& pb = vertices_[b];
        const Eigen::Vector3d mid = 0.5 * (pa + pb);
        Eigen::Vector3d best;
        // A far-away optimum means the quadric is nearly flat along the edge: its minimiser is noise.
        if (q.minimum(best) && (best - mid).squaredNorm() <= (pb - pa).squaredNorm()) {
            c.target = best;
            c.cost = q.eval(best);
            return c;
        }
        const double cost_a = q.eval(pa), cost_b = q.eval(pb), cost_mid = q.eval(mid);
        c.cost = std::min(cost_mid, std::min(cost_a, cost_b));
        c.target = c.cost == cost_mid ? mid : (c.cost == cost_a ? pa : pb);
        return c;
    }

    /// @brief Drop dead triangles from v's list (they are only ever skipped).
    void compact(int v) {
        std::vector<int>& list = around_[v];
        list.erase(std::remove_if(list.begin(), list.end(), [&](int t) { return !triangle_alive_[t]; }), list.end());
    }

    /// @brief Whether moving a and b to `target` and merging them keeps the surface a manifold and turns no
    /// triangle over.
    bool allowed(int a, int b, const Eigen::Vector3d& target) {
        compact(a);
        compact(b);
        const uint32_t of_a = round_ + 1, of_b_only = round_ + 2;
        round_ += 2;
        size_t neighbourhood = 0;  // distinct vertices around a or b, other than a and b
        for (int t : around_[a])
            for (int k = 0; k < 3; ++k) {
                const int v = triangles_[t](k);
                if (v != a && v != b && mark_[v] != of_a) {
                    mark_[v] = of_a;
                    ++neighbourhood;
                }
            }
        int opposite[2] = {-1, -1};
        int shared = 0;
        for (int t : around_[b]) {
            const Eigen::Vector3i& tri = triangles_[t];
            if (!has_vertex(tri, a)) continue;
            if (shared < 2)
                opposite[shared] = tri(0) != a && tri(0) != b ? tri(0) : (tri(1) != a && tri(1) != b ? tri(1) : tri(2));
            ++shared;
        }
        // Only manifold edges collapse; an interior edge between two boundary vertices would pinch the surface.
        if (shared == 0 || shared > 2) return false;
        if (shared == 2 && boundary_[a] && boundary_[b]) return false;
        for (int t : around_[b]) {
            const Eigen::Vector3i& tri = triangles_[t];
            if (has_vertex(tri, a)) continue;
            for (int k = 0; k < 3; ++k) {
                const int v = tri(k);
                if (v == b) continue;
                if (mark_[v] == of_a) {
                    // Link condition: a and b may share only the neighbours across the collapsing edge.
                    if (v != opposite[0] && v != opposite[1]) return false;
                } else if (mark_[v] != of_b_only) {
                    mark_[v] = of_b_only;
                    ++neighbourhood;
                }
            }
        }
        // Collapsing an edge of a tetrahedron (or of a two-triangle pillow) leaves no surface.
        if (shared == 2 && neighbourhood <= 2) return false;
        auto turns_over = [&](int t, int moved) {
            const Eigen::Vector3i& tri = triangles_[t];
            Eigen::Vector3d p[3] = {vertices_[tri(0)], vertices_[tri(1)], vertices_[tri(2)]};
            const Eigen::Vector3d before = (p[1] - p[0]).cross(p[2] - p[0]);
            for (int k = 0; k < 3; ++k)
                if (tri(k) == moved) p[k] = target;
            const Eigen::Vector3d after = (p[1] - p[0]).cross(p[2] - p[0]);
            return before.squaredNorm() > 0 && !(before.dot(after) > 0);
        };
        for (int t : around_[a])
            if (!has_vertex(triangles_[t], b) && turns_over(t, a)) return false;
        for (int t : around_[b])
            if (!has_vertex(triangles_[t], a) && turns_over(t, b)) return false;
        return true;
    }

    /// @brief Merge b into a at `target` and queue a's edges again.
    void collapse(int a, int b, const Eigen::Vector3d& target) {
        for (int t : around_[b]) {
            Eigen::Vector3i& tri = triangles_[t];
            if (has_vertex(tri, a)) {
                triangle_alive_[t] = 0;
                --live_triangles_;
                continue;
            }
            for (int k = 0; k < 3; ++k)
                if (tri(k) == b) tri(k) = a;
            around_[a].push_back(t);
        }
        around_[b].clear();
        around_[b].shrink_to_fit();
        compact(a);
        vertices_[a] = target;
        quadrics_[a] += quadrics_[b];
        if (!normals_.empty()) normals_[a] = 0.5 * (normals_[a] + normals_[b]);
        if (!colors_.empty()) colors_[a] = 0.5 * (colors_[a] + colors_[b]);
        boundary_[a] = boundary_[a] | boundary_[b];
        vertex_alive_[b] = 0;
        changed_[a] = ++clock_;
        const uint32_t seen = ++round_;
        for (int t : around_[a])
            for (int k = 0; k < 3; ++k) {
                const int v = triangles_[t](k);
                if (v == a || mark_[v] == seen) continue;
                mark_[v] = seen;
                enqueue(a, v);
                std::push_heap(heap_.begin(), heap_.end(), CostlierFirst());
            }
    }

    std::vector<Eigen::Vector3d> vertices_, normals_, colors_;
    std::vector<Eigen::Vector3i> triangles_;
    std::vector<uint8_t> vertex_alive_, triangle_alive_, boundary_;
    std::vector<uint32_t> changed_;  ///< clock_ at each vertex's last change: older queued edges are stale
    uint32_t clock_ = 0;
    std::vector<uint32_t> mark_;   ///< per-vertex scratch marks, valid for one `round_`
    uint32_t round_ = 0;
    std::vector<ErrorQuadric> quadrics_;
    std::vector<std::vector<int>> around_;  ///< triangles of each vertex (dead ones dropped lazily)
    std::vector<Eigen::Vector2i> edge_list_;  ///< the initial edges, until the first fill
    std::vector<QueuedEdge> queued_;
    std::vector<HeapEntry> heap_;
    size_t live_triangles_ = 0;
};

}  // namespace

TriangleMesh simplify_quadric_decimation(const TriangleMesh& mesh, size_t target_number_of_triangles,
                                         double maximum_error, double boundary_weight) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    if (std::isnan(maximum_error) || maximum_error < 0)
        throw InvalidArgument("maximum_error must be >= 0 (INFINITY for no limit), got " +
                              std::to_string(maximum_error));
    if (!std::isfinite(boundary_weight) || boundary_weight < 0)
        throw InvalidArgument("boundary_weight must be finite and >= 0, got " + std::to_string(boundary_weight));
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (!mesh.vertices[v].allFinite()) throw InvalidArgument("vertex " + std::to_string(v) + " is not finite");
    if (mesh.triangles.size() <= target_number_of_triangles) return mesh;
    Decimator decimator(mesh, boundary_weight);
    decimator.run(target_number_of_triangles, maximum_error);
    return decimator.result(mesh);
}

}  // namespace o3d::geometry
