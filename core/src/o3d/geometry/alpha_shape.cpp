// SPDX-License-Identifier: MIT
#include "o3d/geometry/alpha_shape.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/geometry/tetra_mesh_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// The face opposite corner k of a positively oriented tetra (0 1 2 3), wound so its normal points away
/// from corner k: then the four faces of a kept tetra are outward as listed.
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// +1 / -1: kept, with the sign of det[b-a, c-a, d-a]; 0: circumradius > alpha or zero volume.
int8_t classify(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector4i& t, double alpha2) {
    const Eigen::Vector3d& a = pts[static_cast<size_t>(t(0))];
    const Eigen::Vector3d u = pts[static_cast<size_t>(t(1))] - a;
    const Eigen::Vector3d v = pts[static_cast<size_t>(t(2))] - a;
    const Eigen::Vector3d w = pts[static_cast<size_t>(t(3))] - a;
    const Eigen::Vector3d vxw = v.cross(w);
    const double det = u.dot(vxw);
    // Circumcentre - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 det). Comparing
    // |numerator|^2 <= (2 det alpha)^2 avoids the division, so a flat tetra (det = 0) fails the test
    // instead of producing inf / NaN.
    const Eigen::Vector3d num = u.squaredNorm() * vxw + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v);
    const double twice_det = 2.0 * det;
    if (det == 0.0 || !(num.squaredNorm() <= twice_det * twice_det * alpha2)) return 0;
    return det > 0.0 ? 1 : -1;
}

/// Face (b, c) of a bucket keyed by its smallest vertex, and the slot 4 * tetra + corner it came from.
struct BucketFace {
    uint64_t rest;
    uint64_t slot;
    bool operator<(const BucketFace& o) const { return rest < o.rest || (rest == o.rest && slot < o.slot); }
};

void check_inputs(const PointCloud& cloud, double alpha) {
    if (!std::isfinite(alpha) || alpha <= 0.0)
        throw InvalidArgument("alpha shape: alpha must be finite and > 0, got " + std::to_string(alpha));
    if (cloud.size() < 4)
        throw InvalidArgument("alpha shape: needs at least 4 points, got " + std::to_string(cloud.size()));
    for (size_t i = 0; i < cloud.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("alpha shape: point " + std::to_string(i) + " is not finite");
}

}  // namespace

TriangleMesh create_from_point_cloud_alpha_shape(const PointCloud& cloud, double alpha, const TetraMesh* tetra_mesh,
                                                 const std::vector<size_t>* point_map, int num_threads) {
    check_inputs(cloud, alpha);
    TetraMeshFromPoints own;
    if (!tetra_mesh) {
        own = create_tetra_mesh_from_points(cloud.points);
        tetra_mesh = &own.mesh;
        point_map = &own.point_map;
    }
    const std::vector<Eigen::Vector3d>& v = tetra_mesh->vertices;
    const std::vector<Eigen::Vector4i>& tetras = tetra_mesh->tetras;
    validate_tetras(*tetra_mesh);
    for (size_t i = 0; i < v.size(); ++i)
        if (!v[i].allFinite())
            throw InvalidArgument("alpha shape: tetra-mesh vertex " + std::to_string(i) + " is not finite");
    if (point_map) {
        if (point_map->size() != v.size())
            throw InvalidArgument("alpha shape: point_map has " + std::to_string(point_map->size()) +
                                  " entries for " + std::to_string(v.size()) + " tetra-mesh vertices");
        for (size_t i = 0; i < point_map->size(); ++i)
            if ((*point_map)[i] >= cloud.size())
                throw InvalidArgument("alpha shape: point_map[" + std::to_string(i) + "] = " +
                                      std::to_string((*point_map)[i]) + " is outside the cloud");
    } else if (v.size() != cloud.size()) {
        throw InvalidArgument("alpha shape: a tetra mesh with " + std::to_string(v.size()) +
                              " vertices for a cloud of " + std::to_string(cloud.size()) + " points needs a point_map");
    }

    const int64_t num_tetras = static_cast<int64_t>(tetras.size());
    const int threads = utility::resolve_num_threads(num_threads);
    const double alpha2 = alpha * alpha;  // inf for a huge alpha: every non-flat tetra is kept

    // 1. The alpha test, independently per tetra.
    std::vector<int8_t> kept(tetras.size());
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t t = 0; t < num_tetras; ++t)
        kept[static_cast<size_t>(t)] = classify(v, tetras[static_cast<size_t>(t)], alpha2);

    // 2. Bucket the kept faces by their smallest vertex (a counting sort: one pass, no hashing). Each face
    //    of a tetrahedralization is in at most two tetras, so a face is on the boundary iff it is alone in
    //    its bucket with its other two vertices (a face in three or more, possible only in a broken
    //    user-given mesh, is not boundary either).
    const size_t nv = v.size();
    std::vector<uint64_t> start(nv + 1, 0);
    auto sorted_face = [&](size_t t, int k) {
        const Eigen::Vector4i& q = tetras[t];
        int a = q(kFace[k][0]), b = q(kFace[k][1]), c = q(kFace[k][2]);
        if (a > b) std::swap(a, b);
        if (b > c) std::swap(b, c);
        if (a > b) std::swap(a, b);
        return Eigen::Vector3i(a, b, c);
    };
    for (size_t t = 0; t < tetras.size(); ++t)
        if (kept[t])
            for (int k = 0; k < 4; ++k) ++start[static_cast<size_t>(sorted_face(t, k)(0)) + 1];
    for (size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
    std::vector<BucketFace> faces(start[nv]);
    {
        std::vector<uint64_t> fill(start.begin(), start.end() - 1);
        for (size_t t = 0; t < tetras.size(); ++t) {
            if (!kept[t]) continue;
            for (int k = 0; k < 4; ++k) {
                const Eigen::Vector3i f = sorted_face(t, k);
                faces[fill[static_cast<size_t>(f(0))]++] = {
                    (static_cast<uint64_t>(static_cast<uint32_t>(f(1))) << 32) | static_cast<uint32_t>(f(2)),
                    4 * static_cast<uint64_t>(t) + static_cast<uint64_t>(k)};
            }
        }
    }
    std::vector<uint8_t> boundary(4 * tetras.size(), 0);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256)
    for (int64_t b = 0; b < static_cast<int64_t>(nv); ++b) {
        BucketFace* first = faces.data() + start[static_cast<size_t>(b)];
        BucketFace* last = faces.data() + start[static_cast<size_t>(b) + 1];
        std::sort(first, last);
        for (BucketFace* f = first; f != last;) {
            BucketFace* g = f + 1;
            while (g != last && g->rest == f->rest) ++g;
            if (g - f == 1) boundary[f->slot] = 1;
            f = g;
        }
    }

    // 3. Boundary triangles in (tetra, corner) order, outward; then the vertices they use, in order.
    TriangleMesh mesh;
    std::vector<int> new_index(nv, -1);
    for (size_t s = 0; s < boundary.size(); ++s) {
        if (!boundary[s]) continue;
        const size_t t = s / 4;
        const int k = static_cast<int>(s % 4);
        const Eigen::Vector4i& q = tetras[t];
        Eigen::Vector3i tri(q(kFace[k][0]), q(kFace[k][1]), q(kFace[k][2]));
        if (kept[t] < 0) std::swap(tri(1), tri(2));
        for (int j = 0; j < 3; ++j) new_index[static_cast<size_t>(tri(j))] = 0;
        mesh.triangles.push_back(tri);
    }
    std::vector<size_t> used;
    for (size_t i = 0; i < nv; ++i)
        if (new_index[i] == 0) {
            new_index[i] = static_cast<int>(used.size());
            used.push_back(i);
        }
    for (Eigen::Vector3i& tri : mesh.triangles)
        for (int j = 0; j < 3; ++j) tri(j) = new_index[static_cast<size_t>(tri(j))];
    auto source = [&](size_t vertex) { return point_map ? (*point_map)[vertex] : vertex; };
    mesh.vertices.reserve(used.size());
    for (size_t i : used) mesh.vertices.push_back(v[i]);
    if (cloud.has_normals())
        for (size_t i : used) mesh.vertex_normals.push_back(cloud.normals[source(i)]);
    if (cloud.has_colors())
        for (size_t i : used) mesh.vertex_colors.push_back(cloud.colors[source(i)]);
    return mesh;
}

}  // namespace o3d::geometry
