// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_intersection_queries.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>

#include "o3d/geometry/mesh_self_intersection.h"
#include "o3d/geometry/triangle_box_grid.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

using detail::BoxGrid;
using detail::TriangleBox;
using detail::add_boxes;
using detail::boxes_overlap;
using detail::share_vertex;


bool intersect(const TriangleMesh& ma, int ta, const TriangleMesh& mb, int tb) {
    const Eigen::Vector3i &p = ma.triangles[ta], &q = mb.triangles[tb];
    const auto &u = ma.vertices, &v = mb.vertices;
    return triangles_intersect(u[p(0)], u[p(1)], u[p(2)], v[q(0)], v[q(1)], v[q(2)]);
}

}  // namespace

std::vector<Eigen::Vector2i> self_intersecting_triangles(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    std::vector<TriangleBox> boxes;
    add_boxes(mesh, 0, boxes);
    if (boxes.size() < 2) return {};
    const BoxGrid grid(boxes);
    std::vector<Eigen::Vector2i> out;
    std::atomic<bool> never{false};
    grid.for_each_overlap(
        [&](size_t a, size_t b) {
            const int ta = boxes[a].index, tb = boxes[b].index;
            if (share_vertex(mesh.triangles[ta], mesh.triangles[tb])) return;
            if (!intersect(mesh, ta, mesh, tb)) return;
#pragma omp critical(o3d_self_intersecting_triangles)
            out.emplace_back(std::min(ta, tb), std::max(ta, tb));
        },
        never);
    // Found in whatever order the threads reach the cells: sorting makes the list the same for any count.
    std::sort(out.begin(), out.end(), [](const Eigen::Vector2i& x, const Eigen::Vector2i& y) {
        return x(0) != y(0) ? x(0) < y(0) : x(1) < y(1);
    });
    return out;
}

bool meshes_intersect(const TriangleMesh& a, const TriangleMesh& b) {
    validate_triangles(a);
    validate_triangles(b);
    std::vector<TriangleBox> boxes_a, boxes_b;
    add_boxes(a, 0, boxes_a);
    add_boxes(b, 1, boxes_b);
    if (boxes_a.empty() || boxes_b.empty()) return false;
    // Only triangles inside the overlap of the two meshes' boxes can meet (Open3D's first test).
    auto bound = [](const std::vector<TriangleBox>& boxes) {
        TriangleBox all{boxes[0].lo, boxes[0].hi, 0, 0};
        for (const TriangleBox& x : boxes) {
            all.lo = all.lo.cwiseMin(x.lo);
            all.hi = all.hi.cwiseMax(x.hi);
        }
        return all;
    };
    const TriangleBox bound_a = bound(boxes_a), bound_b = bound(boxes_b);
    if (!boxes_overlap(bound_a, bound_b)) return false;
    const TriangleBox common{bound_a.lo.cwiseMax(bound_b.lo), bound_a.hi.cwiseMin(bound_b.hi), 0, 0};
    std::vector<TriangleBox> boxes;
    for (const auto* part : {&boxes_a, &boxes_b})
        for (const TriangleBox& x : *part)
            if (boxes_overlap(x, common)) boxes.push_back(x);
    if (boxes.size() < 2) return false;
    const BoxGrid grid(boxes);
    std::atomic<bool> found{false};
    grid.for_each_overlap(
        [&](size_t i, size_t j) {
            const TriangleBox &x = boxes[i], &y = boxes[j];
            if (x.mesh == y.mesh) return;
            const bool hit = x.mesh == 0 ? intersect(a, x.index, b, y.index) : intersect(a, y.index, b, x.index);
            if (hit) found.store(true, std::memory_order_relaxed);
        },
        found);
    return found.load();
}

}  // namespace o3d::geometry
