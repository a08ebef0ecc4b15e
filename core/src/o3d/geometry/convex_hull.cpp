// SPDX-License-Identifier: MIT
#include "o3d/geometry/convex_hull.h"

#include <Eigen/Geometry>
#include <cstdint>
#include <cstdio>
#include <string>

#include "o3d/geometry/qhull_support.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

ConvexHull compute_convex_hull(const std::vector<Eigen::Vector3d>& points, bool joggle_inputs) {
    if (points.size() < 4)
        throw InvalidArgument("a convex hull needs at least 4 points, got " + std::to_string(points.size()));
    if (points.size() > static_cast<size_t>(INT32_MAX))
        throw InvalidArgument("Qhull takes at most 2^31 - 1 points, got " + std::to_string(points.size()));
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite()) throw InvalidArgument("point " + std::to_string(i) + " is not finite");
    // Eigen::Vector3d is three packed doubles, so the vector is already Qhull's row-major coordT array.
    static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(coordT), "Vector3d must be 3 packed doubles");
    coordT* coords = const_cast<coordT*>(points[0].data());  // Qhull copies before joggling (ismalloc False)

    detail::QhullRun run;
    qhT* qh = run.get();
    detail::QhullErrorStream errors;
    char flags[32];
    std::snprintf(flags, sizeof flags, "qhull Qt%s", joggle_inputs ? " QJ" : "");
    const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords, False, flags, nullptr,
                                       errors.file());
    if (exit_code != 0) {
        const std::string reason = errors.first_paragraph();
        throw InvalidArgument("Qhull could not build the hull (exit code " + std::to_string(exit_code) + ")" +
                              (joggle_inputs ? "" : "; the points may be coplanar (try joggle_inputs)") +
                              (reason.empty() ? "" : ": " + reason));
    }

    ConvexHull hull;
    std::vector<int> vertex_of_point(points.size(), -1);
    facetT* facet;
    FORALLfacets {
        int corner[3];
        int k = 0;
        vertexT *vertex, **vertexp;
        FOREACHvertex_(facet->vertices) {
            if (k == 3) break;
            const int pid = qh_pointid(qh, vertex->point);
            int& v = vertex_of_point[static_cast<size_t>(pid)];
            if (v < 0) {
                v = static_cast<int>(hull.point_indices.size());
                hull.point_indices.push_back(pid);
                hull.mesh.vertices.push_back(points[static_cast<size_t>(pid)]);
            }
            corner[k++] = v;
        }
        if (k != 3) continue;
        Eigen::Vector3i tri(corner[0], corner[1], corner[2]);
        const Eigen::Vector3d& a = hull.mesh.vertices[tri(0)];
        const Eigen::Vector3d cross = (hull.mesh.vertices[tri(1)] - a).cross(hull.mesh.vertices[tri(2)] - a);
        const Eigen::Vector3d outward(facet->normal[0], facet->normal[1], facet->normal[2]);
        if (cross.dot(outward) < 0.0) std::swap(tri(1), tri(2));
        hull.mesh.triangles.push_back(tri);
    }
    return hull;
}

}  // namespace o3d::geometry
