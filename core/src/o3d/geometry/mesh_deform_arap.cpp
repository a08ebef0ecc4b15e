// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_deform_arap.h"

#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

void check_inputs(const TriangleMesh& mesh, const std::vector<int>& indices,
                  const std::vector<Eigen::Vector3d>& positions, int max_iter, ArapEnergy energy,
                  double smoothed_alpha) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("deform_as_rigid_as_possible: the mesh has no vertices");
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (!mesh.vertices[v].allFinite())
            throw InvalidArgument("deform_as_rigid_as_possible: vertex " + std::to_string(v) + " is not finite");
    if (indices.size() != positions.size())
        throw InvalidArgument("deform_as_rigid_as_possible: " + std::to_string(indices.size()) +
                              " constraint indices but " + std::to_string(positions.size()) + " positions");
    if (indices.empty())
        throw InvalidArgument("deform_as_rigid_as_possible: no constraints (the system would be singular)");
    std::vector<uint8_t> seen(mesh.vertices.size(), 0);
    for (size_t k = 0; k < indices.size(); ++k) {
        const int v = indices[k];
        if (v < 0 || static_cast<size_t>(v) >= mesh.vertices.size())
            throw InvalidArgument("deform_as_rigid_as_possible: constraint index " + std::to_string(v) +
                                  " out of range [0, " + std::to_string(mesh.vertices.size()) + ")");
        if (seen[v]) throw InvalidArgument("deform_as_rigid_as_possible: vertex " + std::to_string(v) +
                                           " is constrained twice");
        seen[v] = 1;
        if (!positions[k].allFinite())
            throw InvalidArgument("deform_as_rigid_as_possible: constraint position " + std::to_string(k) +
                                  " is not finite");
    }
    if (max_iter < 0)
        throw InvalidArgument("deform_as_rigid_as_possible: max_iter must be >= 0, got " + std::to_string(max_iter));
    if (energy != ArapEnergy::Spokes && energy != ArapEnergy::Smoothed)
        throw InvalidArgument("deform_as_rigid_as_possible: unknown energy " +
                              std::to_string(static_cast<int>(energy)) + " (expected 0 or 1)");
    if (!std::isfinite(smoothed_alpha))
        throw InvalidArgument("deform_as_rigid_as_possible: smoothed_alpha must be finite");
}

/// @brief Every vertex's neighbours (ascending) with the cotangent weight of the joining edge (CSR).
struct WeightedNeighbours {
    std::vector<int> offsets;
    std::vector<int> neighbours;
    std::vector<double> weights;
};

/// @brief Open3D's cotangent weights: per edge the mean, over the triangle sides on it, of the cotangent
/// of the angle opposite the side; a negative mean becomes 0. A zero-area triangle contributes 0.
WeightedNeighbours cotangent_neighbours(const TriangleMesh& mesh) {
    const MeshEdges edges = mesh_edges(mesh);
    std::vector<double> sum(edges.size(), 0.0);
    std::vector<int> count(edges.size(), 0);
    for (size_t s = 0; s < edges.side_edge.size(); ++s) {
        const Eigen::Vector3i& tri = mesh.triangles[s / 3];
        const int k = static_cast<int>(s % 3);
        const Eigen::Vector3d& opposite = mesh.vertices[tri((k + 2) % 3)];
        const Eigen::Vector3d a = mesh.vertices[tri(k)] - opposite, b = mesh.vertices[tri((k + 1) % 3)] - opposite;
        const double sine = a.cross(b).norm();  // |a||b| sin, so dot / cross = cot
        if (sine > 0) sum[edges.side_edge[s]] += a.dot(b) / sine;
        ++count[edges.side_edge[s]];
    }
    const size_t nv = mesh.vertices.size();
    WeightedNeighbours out;
    out.offsets.assign(nv + 1, 0);
    for (const Eigen::Vector2i& e : edges.endpoints)
        if (e(0) != e(1)) {
            ++out.offsets[e(0) + 1];
            ++out.offsets[e(1) + 1];
        }
    for (size_t v = 0; v < nv; ++v) out.offsets[v + 1] += out.offsets[v];
    std::vector<std::pair<int, double>> entries(out.offsets[nv]);
    std::vector<int> fill(out.offsets.begin(), out.offsets.end() - 1);
    for (size_t e = 0; e < edges.size(); ++e) {
        const int a = edges.endpoints[e](0), b = edges.endpoints[e](1);
        if (a == b) continue;
        const double w = std::max(0.0, sum[e] / count[e]);
        entries[fill[a]++] = {b, w};
        entries[fill[b]++] = {a, w};
    }
    out.neighbours.resize(entries.size());
    out.weights.resize(entries.size());
    for (size_t v = 0; v < nv; ++v) {
        std::sort(entries.begin() + out.offsets[v], entries.begin() + out.offsets[v + 1]);
        for (int p = out.offsets[v]; p < out.offsets[v + 1]; ++p) {
            out.neighbours[p] = entries[p].first;
            out.weights[p] = entries[p].second;
        }
    }
    return out;
}

/// @brief Below this many vertices the per-vertex loops run on one thread: a parallel region costs more than
/// the work (OpenMP's spinning threads dominate on a small mesh).
constexpr int kParallelMinVertices = 512;

int find_root(std::vector<int>& parent, int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

/// @brief Vertices whose position is given: the constrained ones at their targets, and every vertex of a
/// part (joined by positive weights) without a constraint at its input position. -1 marks a free vertex.
std::vector<int> fixed_targets(const TriangleMesh& mesh, const WeightedNeighbours& around,
                               const std::vector<int>& indices, std::vector<Eigen::Vector3d>& target) {
    const int nv = static_cast<int>(mesh.vertices.size());
    std::vector<int> parent(nv);
    std::iota(parent.begin(), parent.end(), 0);
    for (int v = 0; v < nv; ++v)
        for (int p = around.offsets[v]; p < around.offsets[v + 1]; ++p)
            if (around.weights[p] > 0) parent[find_root(parent, v)] = find_root(parent, around.neighbours[p]);
    std::vector<uint8_t> anchored(nv, 0);
    for (const int v : indices) anchored[find_root(parent, v)] = 1;
    std::vector<int> role(nv, -1);  // -1 free, 0 fixed
    target = mesh.vertices;
    for (int v = 0; v < nv; ++v)
        if (!anchored[find_root(parent, v)]) role[v] = 0;
    for (const int v : indices) role[v] = 0;
    return role;
}

}  // namespace

TriangleMesh deform_as_rigid_as_possible(const TriangleMesh& mesh, const std::vector<int>& constraint_vertex_indices,
                                         const std::vector<Eigen::Vector3d>& constraint_vertex_positions,
                                         int max_iter, ArapEnergy energy, double smoothed_alpha, int num_threads) {
    check_inputs(mesh, constraint_vertex_indices, constraint_vertex_positions, max_iter, energy, smoothed_alpha);
    TriangleMesh out;
    out.vertices = mesh.vertices;
    out.triangles = mesh.triangles;
    if (max_iter == 0) return out;

    const int nv = static_cast<int>(mesh.vertices.size());
    const WeightedNeighbours around = cotangent_neighbours(mesh);
    std::vector<Eigen::Vector3d> target;
    std::vector<int> free_index = fixed_targets(mesh, around, constraint_vertex_indices, target);
    for (size_t k = 0; k < constraint_vertex_indices.size(); ++k)
        target[constraint_vertex_indices[k]] = constraint_vertex_positions[k];
    std::vector<int> free_vertices;
    for (int v = 0; v < nv; ++v)
        if (free_index[v] < 0) {
            free_index[v] = static_cast<int>(free_vertices.size());
            free_vertices.push_back(v);
        } else {
            free_index[v] = -1;
        }
    const int nf = static_cast<int>(free_vertices.size());

    // Open3D's system keeps the constrained rows as identity rows (a non-symmetric matrix it factorises by
    // LU); moving the constrained columns to the right-hand side leaves the same solution and a symmetric
    // positive definite grounded Laplacian on the free vertices.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    if (nf > 0) {
        std::vector<Eigen::Triplet<double>> triplets;
        for (int f = 0; f < nf; ++f) {
            const int v = free_vertices[f];
            double diagonal = 0;
            for (int p = around.offsets[v]; p < around.offsets[v + 1]; ++p) {
                const double w = around.weights[p];
                diagonal += w;
                const int g = free_index[around.neighbours[p]];
                if (g >= 0 && w != 0) triplets.emplace_back(f, g, -w);
            }
            triplets.emplace_back(f, f, diagonal);
        }
        Eigen::SparseMatrix<double> laplacian(nf, nf);
        laplacian.setFromTriplets(triplets.begin(), triplets.end());
        solver.compute(laplacian);
        if (solver.info() != Eigen::Success)
            throw InvalidArgument("deform_as_rigid_as_possible: the constrained Laplacian could not be factorised");
    }

    double area = 0;
    if (energy == ArapEnergy::Smoothed)
        for (size_t t = 0; t < mesh.triangles.size(); ++t) area += triangle_area(mesh, t);

    const std::vector<Eigen::Vector3d>& original = mesh.vertices;
    std::vector<Eigen::Vector3d>& deformed = out.vertices;
    std::vector<Eigen::Matrix3d> rotation(nv, Eigen::Matrix3d::Identity()), previous = rotation;
    Eigen::MatrixX3d rhs(nf, 3);
    const int threads = utility::resolve_num_threads(num_threads);
    for (int iter = 0; iter < max_iter; ++iter) {
        std::swap(rotation, previous);
        const bool smooth = energy == ArapEnergy::Smoothed && iter > 0;
        // Local step: the rotation of each one-ring that best maps its input spokes onto the deformed ones.
#pragma omp parallel for schedule(static) num_threads(threads) if (nv >= kParallelMinVertices)
        for (int v = 0; v < nv; ++v) {
            Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero(), neighbour_rotations = Eigen::Matrix3d::Zero();
            for (int p = around.offsets[v]; p < around.offsets[v + 1]; ++p) {
                const int j = around.neighbours[p];
                covariance += around.weights[p] * (original[v] - original[j]) * (deformed[v] - deformed[j]).transpose();
                if (smooth) neighbour_rotations += previous[j];
            }
            const int count = around.offsets[v + 1] - around.offsets[v];
            if (smooth && count > 0)
                covariance += (2.0 * smoothed_alpha * area / count) * neighbour_rotations.transpose();
            const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
            Eigen::Matrix3d u = svd.matrixU();
            const Eigen::Matrix3d& w = svd.matrixV();
            // A reflection fits better than any rotation: flip the least significant axis instead.
            if ((w * u.transpose()).determinant() < 0) u.col(2) = -u.col(2);
            rotation[v] = w * u.transpose();
        }
        // Global step: positions that best fit the averaged rotated spokes, the fixed vertices held.
#pragma omp parallel for schedule(static) num_threads(threads) if (nf >= kParallelMinVertices)
        for (int f = 0; f < nf; ++f) {
            const int v = free_vertices[f];
            Eigen::Vector3d b = Eigen::Vector3d::Zero();
            for (int p = around.offsets[v]; p < around.offsets[v + 1]; ++p) {
                const int j = around.neighbours[p];
                const double w = around.weights[p];
                b += (0.5 * w) * ((rotation[v] + rotation[j]) * (original[v] - original[j]));
                if (free_index[j] < 0) b += w * target[j];
            }
            rhs.row(f) = b.transpose();
        }
        if (nf > 0) {
            const Eigen::MatrixX3d solution = solver.solve(rhs);
            for (int f = 0; f < nf; ++f) deformed[free_vertices[f]] = solution.row(f).transpose();
        }
        for (int v = 0; v < nv; ++v)
            if (free_index[v] < 0) deformed[v] = target[v];
    }
    return out;
}

}  // namespace o3d::geometry
