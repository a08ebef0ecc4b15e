// SPDX-License-Identifier: MIT
#include "o3d/geometry/tetra_mesh.h"

#include <Eigen/Geometry>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include "o3d/geometry/qhull_support.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// Qhull options for the Delaunay step (the lower hull of the points lifted onto the paraboloid):
///  d   Delaunay: lift to (x, y, z, x^2 + y^2 + z^2) and keep the lower facets.
///  Qbb scale the lifted coordinate to the range of the others; without it the paraboloid coordinate
///      dwarfs x, y, z and costs precision.
///  Qt  triangulate non-simplicial facets (merged nearly-cospherical cells), so that every facet is a tetra.
///  Qz  add a point at infinity above the paraboloid: Qhull's documented cure for cospherical input, and
///      what lets a set such as the 8 cube corners (all on one sphere) be tetrahedralized at all; the
///      facets touching it are upper-Delaunay and dropped.
///  Q5  skip the final check of every point against the outer planes (qh_check_maxout). It only bounds
///      the reported outer-plane distance, which we never use, and costs ~30% of the run on 50k points.
constexpr const char* kDelaunayOptions = "qhull d Qbb Qt Qz Q5";

/// qh_new_qhull without its output preparation: that pass (qh_prepare_output) also marks the "good"
/// facets of every facet (qh_findgood_all, ~10% of the run) which we do not use — we read
/// upperdelaunay directly. The steps and the error trap mirror qh_new_qhull. Only C objects live in
/// this frame, so Qhull's longjmp on error skips no destructor.
int run_delaunay(qhT* qh, int num_points, coordT* coords, char* options, FILE* errfile) {
    qh_init_A(qh, nullptr, nullptr, errfile, 0, nullptr);
    int exit_code = setjmp(qh->errexit);
    if (exit_code == 0) {
        qh->NOerrexit = False;
        qh_initflags(qh, options);
        qh->PROJECTdelaunay = True;  // as qh_new_qhull does for 'd': lift the points onto the paraboloid
        qh_init_B(qh, coords, num_points, 3, False);
        qh_qhull(qh);
        qh_check_output(qh);  // no-op unless verification was asked for
        if (qh->TRIangulate && !qh->hasTriangulation) qh_triangulate(qh);  // 'Qt'
    }
    qh->NOerrexit = True;
    return exit_code;
}

}  // namespace

TetraMeshFromPoints create_tetra_mesh_from_points(const std::vector<Eigen::Vector3d>& points) {
    const size_t n = points.size();
    if (n < 4) throw InvalidArgument("a tetrahedral mesh needs at least 4 points, got " + std::to_string(n));
    if (n > static_cast<size_t>(INT32_MAX))
        throw InvalidArgument("Qhull takes at most 2^31 - 1 points, got " + std::to_string(n));
    Eigen::Vector3d lo = points[0], hi = points[0];
    for (size_t i = 0; i < n; ++i) {
        if (!points[i].allFinite()) throw InvalidArgument("point " + std::to_string(i) + " is not finite");
        lo = lo.cwiseMin(points[i]);
        hi = hi.cwiseMax(points[i]);
    }
    // Delaunay is translation invariant, but the lift |p|^2 is not: far from the origin it cancels most
    // significant bits. Centring on the bounding box keeps the lifted coordinate as precise as possible.
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    std::vector<coordT> coords(3 * n);
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) coords[3 * i + k] = points[i](k) - centre(k);

    detail::QhullRun run;
    qhT* qh = run.get();
    detail::QhullErrorStream errors;
    char options[64];
    std::snprintf(options, sizeof options, "%s", kDelaunayOptions);
    const int exit_code = run_delaunay(qh, static_cast<int>(n), coords.data(), options, errors.file());
    if (exit_code != 0) {
        const std::string reason = errors.first_paragraph();
        throw InvalidArgument("Qhull could not tetrahedralize the points (exit code " + std::to_string(exit_code) +
                              "); they may be coplanar, collinear or coincident" +
                              (reason.empty() ? "" : ": " + reason));
    }

    // Pass 1: the tetras as input point ids, and which points are used.
    std::vector<Eigen::Vector4i> tetras;
    tetras.reserve(static_cast<size_t>(qh->num_facets));
    std::vector<int> vertex_of_point(n, 0);  // 1 = used, then the vertex index
    facetT* facet;
    FORALLfacets {
        if (facet->upperdelaunay) continue;
        Eigen::Vector4i tet;
        int k = 0;
        bool finite = true;
        vertexT *vertex, **vertexp;
        FOREACHvertex_(facet->vertices) {
            if (k == 4) break;
            const int pid = qh_pointid(qh, vertex->point);
            // The point at infinity (Qz) has an id past the input; lower facets never hold it, but check.
            if (pid < 0 || static_cast<size_t>(pid) >= n) {
                finite = false;
                break;
            }
            tet(k++) = pid;
        }
        if (!finite || k != 4) continue;
        for (int j = 0; j < 4; ++j) vertex_of_point[static_cast<size_t>(tet(j))] = 1;
        tetras.push_back(tet);
    }

    // Vertices in ascending input order: deterministic and independent of Qhull's facet order.
    TetraMeshFromPoints out;
    int next = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!vertex_of_point[i]) continue;
        vertex_of_point[i] = next++;
        out.point_map.push_back(i);
        out.mesh.vertices.push_back(points[i]);
    }
    const std::vector<Eigen::Vector3d>& v = out.mesh.vertices;
    for (Eigen::Vector4i& t : tetras) {
        for (int j = 0; j < 4; ++j) t(j) = vertex_of_point[static_cast<size_t>(t(j))];
        // Positive orientation lets callers read outward faces off the index order.
        const Eigen::Vector3d& a = v[static_cast<size_t>(t(0))];
        const double det = (v[static_cast<size_t>(t(1))] - a)
                               .cross(v[static_cast<size_t>(t(2))] - a)
                               .dot(v[static_cast<size_t>(t(3))] - a);
        if (det < 0.0) std::swap(t(2), t(3));
    }
    out.mesh.tetras = std::move(tetras);
    return out;
}

}  // namespace o3d::geometry
