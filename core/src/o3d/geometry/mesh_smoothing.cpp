// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_smoothing.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_filter_detail.h"
#include "o3d/geometry/mesh_normals_util.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace detail {

void check_filter_input(const TriangleMesh& mesh, int number_of_iterations, FilterScope scope) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    if (number_of_iterations < 0)
        throw InvalidArgument("number_of_iterations must be >= 0, got " + std::to_string(number_of_iterations));
    const int s = static_cast<int>(scope);
    if (s < 0 || s > 3) throw InvalidArgument("unknown filter scope " + std::to_string(s) + " (expected 0..3)");
}

}  // namespace detail
namespace {

void check_finite(double x, const char* name) {
    if (!std::isfinite(x)) throw InvalidArgument(std::string(name) + " must be finite, got " + std::to_string(x));
}

}  // namespace

namespace detail {

TriangleMesh apply_vertex_filter(const TriangleMesh& mesh, int number_of_iterations, const std::vector<FilterStep>& steps,
                                 FilterScope scope, int num_threads) {
    TriangleMesh out = mesh;
    const bool positions = scope == FilterScope::All || scope == FilterScope::Vertex;
    const bool normals = (scope == FilterScope::All || scope == FilterScope::Normal) && mesh.has_vertex_normals();
    const bool colors = (scope == FilterScope::All || scope == FilterScope::Color) && mesh.has_vertex_colors();
    if (number_of_iterations == 0 || (!positions && !normals && !colors)) return out;

    const size_t nv = mesh.vertices.size();
    const VertexNeighbours around = vertex_neighbours(mesh_edges(mesh), nv);
    const int threads = utility::resolve_num_threads(num_threads);
    // Every vertex of a step reads the previous state only: double buffers, swapped after each step.
    std::vector<Eigen::Vector3d> next_p = out.vertices, next_n = out.vertex_normals, next_c = out.vertex_colors;
    for (int it = 0; it < number_of_iterations; ++it) {
        for (const FilterStep& step : steps) {
            const std::vector<Eigen::Vector3d>& p = out.vertices;
            const std::vector<Eigen::Vector3d>& n = out.vertex_normals;
            const std::vector<Eigen::Vector3d>& c = out.vertex_colors;
#pragma omp parallel for schedule(static) num_threads(threads)
            for (int64_t vi = 0; vi < static_cast<int64_t>(nv); ++vi) {
                const size_t v = static_cast<size_t>(vi);
                Eigen::Vector3d sum_p = Eigen::Vector3d::Zero(), sum_n = sum_p, sum_c = sum_p;
                double total = 0;
                for (const int* j = around.begin(v); j != around.end(v); ++j) {
                    const double w =
                        step.kind == FilterStepKind::Laplacian ? 1.0 / ((p[v] - p[*j]).norm() + 1e-12) : 1.0;
                    total += w;
                    if (positions) sum_p += w * p[*j];
                    if (normals) sum_n += w * n[*j];
                    if (colors) sum_c += w * c[*j];
                }
                if (around.count(v) == 0) {  // nothing to average with
                    if (positions) next_p[v] = p[v];
                    if (normals) next_n[v] = n[v];
                    if (colors) next_c[v] = c[v];
                    continue;
                }
                if (step.kind == FilterStepKind::Sharpen) {  // v + strength (|N| v - sum), in Open3D's order
                    if (positions) next_p[v] = p[v] + step.weight * (p[v] * total - sum_p);
                    if (normals) next_n[v] = n[v] + step.weight * (n[v] * total - sum_n);
                    if (colors) next_c[v] = c[v] + step.weight * (c[v] * total - sum_c);
                } else if (step.kind == FilterStepKind::Mean) {
                    const double inv = 1.0 / (1.0 + total);
                    if (positions) next_p[v] = (p[v] + sum_p) * inv;
                    if (normals) next_n[v] = (n[v] + sum_n) * inv;
                    if (colors) next_c[v] = (c[v] + sum_c) * inv;
                } else {
                    if (positions) next_p[v] = p[v] + step.weight * (sum_p / total - p[v]);
                    if (normals) next_n[v] = n[v] + step.weight * (sum_n / total - n[v]);
                    if (colors) next_c[v] = c[v] + step.weight * (sum_c / total - c[v]);
                }
            }
            if (positions) std::swap(out.vertices, next_p);
            if (normals) std::swap(out.vertex_normals, next_n);
            if (colors) std::swap(out.vertex_colors, next_c);
        }
    }
    if (positions && mesh.has_triangle_normals()) out.triangle_normals = unit_triangle_normals(out);
    return out;
}

}  // namespace detail

TriangleMesh filter_smooth_simple(const TriangleMesh& mesh, int number_of_iterations, FilterScope scope,
                                  int num_threads) {
    detail::check_filter_input(mesh, number_of_iterations, scope);
    return detail::apply_vertex_filter(mesh, number_of_iterations, {{detail::FilterStepKind::Mean, 0.0}}, scope,
                                      num_threads);
}

TriangleMesh filter_smooth_laplacian(const TriangleMesh& mesh, int number_of_iterations, double lambda_filter,
                                     FilterScope scope, int num_threads) {
    detail::check_filter_input(mesh, number_of_iterations, scope);
    check_finite(lambda_filter, "lambda_filter");
    return detail::apply_vertex_filter(mesh, number_of_iterations, {{detail::FilterStepKind::Laplacian, lambda_filter}},
                                      scope, num_threads);
}

TriangleMesh filter_smooth_taubin(const TriangleMesh& mesh, int number_of_iterations, double lambda_filter,
                                  double mu, FilterScope scope, int num_threads) {
    detail::check_filter_input(mesh, number_of_iterations, scope);
    check_finite(lambda_filter, "lambda_filter");
    check_finite(mu, "mu");
    return detail::apply_vertex_filter(
        mesh, number_of_iterations,
        {{detail::FilterStepKind::Laplacian, lambda_filter}, {detail::FilterStepKind::Laplacian, mu}}, scope,
        num_threads);
}

}  // namespace o3d::geometry
