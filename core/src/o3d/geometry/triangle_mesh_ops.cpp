// SPDX-License-Identifier: MIT
#include "o3d/geometry/triangle_mesh_ops.h"

#include <Eigen/Geometry>
#include <climits>
#include <cmath>
#include <string>

#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// Below this many triangles the per-triangle loops are memory-bound and a parallel region costs more than it saves.
constexpr long long kParallelTriangles = 100000;

/// @brief Append `source` onto `target` when `keep`, else drop the target's copy (Open3D's rule: an
/// attribute only one side has would no longer line up with the rows).
template <typename T>
void append_attribute(std::vector<T>& target, bool keep, const std::vector<T>& source) {
    if (!keep) {
        target.clear();
        return;
    }
    target.insert(target.end(), source.begin(), source.end());
}

void normalize_in_place(std::vector<Eigen::Vector3d>& normals) {
    for (Eigen::Vector3d& n : normals) {
        n.normalize();  // Eigen leaves a zero vector unchanged
        if (std::isnan(n(0))) n = Eigen::Vector3d(0, 0, 1);
    }
}

void transform_normals(std::vector<Eigen::Vector3d>& normals, const Eigen::Matrix3d& linear) {
    for (Eigen::Vector3d& n : normals) n = linear * n;
}

}  // namespace

void append(TriangleMesh& target, const TriangleMesh& source) {
    validate_triangles(target);
    validate_triangles(source);
    if (source.vertices.empty()) return;
    const size_t old_vertices = target.vertices.size();
    if (old_vertices + source.vertices.size() > static_cast<size_t>(INT_MAX))
        throw InvalidArgument("the appended mesh would have more than 2^31 - 1 vertices");
    const bool no_vertices = target.vertices.empty();
    const bool no_triangles = target.triangles.empty();
    const bool keep_vertex_normals = (no_vertices || target.has_vertex_normals()) && source.has_vertex_normals();
    const bool keep_vertex_colors = (no_vertices || target.has_vertex_colors()) && source.has_vertex_colors();
    const bool keep_triangle_normals =
        (no_triangles || target.has_triangle_normals()) && source.has_triangle_normals();
    const bool keep_uvs = (no_triangles || target.has_triangle_uvs()) && source.has_triangle_uvs();
    const bool keep_material_ids =
        (no_triangles || target.has_triangle_material_ids()) && source.has_triangle_material_ids();
    const int material_shift = static_cast<int>(target.textures.size());

    append_attribute(target.vertex_normals, keep_vertex_normals, source.vertex_normals);
    append_attribute(target.vertex_colors, keep_vertex_colors, source.vertex_colors);
    append_attribute(target.triangle_normals, keep_triangle_normals, source.triangle_normals);
    append_attribute(target.triangle_uvs, keep_uvs, source.triangle_uvs);
    const size_t old_ids = target.triangle_material_ids.size();
    append_attribute(target.triangle_material_ids, keep_material_ids, source.triangle_material_ids);
    if (keep_material_ids)
        for (size_t i = old_ids; i < target.triangle_material_ids.size(); ++i)
            target.triangle_material_ids[i] += material_shift;
    target.textures.insert(target.textures.end(), source.textures.begin(), source.textures.end());

    target.vertices.insert(target.vertices.end(), source.vertices.begin(), source.vertices.end());
    const Eigen::Vector3i shift = Eigen::Vector3i::Constant(static_cast<int>(old_vertices));
    target.triangles.reserve(target.triangles.size() + source.triangles.size());
    for (const Eigen::Vector3i& tri : source.triangles) target.triangles.push_back(tri + shift);
}

Eigen::Vector3d min_bound(const TriangleMesh& mesh) {
    if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d lo = mesh.vertices[0];
    for (const Eigen::Vector3d& v : mesh.vertices) lo = lo.cwiseMin(v);
    return lo;
}

Eigen::Vector3d max_bound(const TriangleMesh& mesh) {
    if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d hi = mesh.vertices[0];
    for (const Eigen::Vector3d& v : mesh.vertices) hi = hi.cwiseMax(v);
    return hi;
}

Eigen::Vector3d center(const TriangleMesh& mesh) {
    if (mesh.vertices.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& v : mesh.vertices) sum += v;
    return sum / static_cast<double>(mesh.vertices.size());
}

void transform(TriangleMesh& mesh, const Eigen::Matrix4d& transformation) {
    if (!transformation.allFinite()) throw InvalidArgument("transformation has a non-finite entry");
    for (Eigen::Vector3d& v : mesh.vertices) {
        const Eigen::Vector4d h = transformation * v.homogeneous();
        v = h.head<3>() / h(3);
    }
    const Eigen::Matrix3d linear = transformation.topLeftCorner<3, 3>();
    transform_normals(mesh.vertex_normals, linear);
    transform_normals(mesh.triangle_normals, linear);
}

void translate(TriangleMesh& mesh, const Eigen::Vector3d& translation, bool relative) {
    if (!translation.allFinite()) throw InvalidArgument("translation has a non-finite entry");
    const Eigen::Vector3d shift = relative ? translation : Eigen::Vector3d(translation - center(mesh));
    for (Eigen::Vector3d& v : mesh.vertices) v += shift;
}

void rotate(TriangleMesh& mesh, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& c) {
    if (!rotation.allFinite()) throw InvalidArgument("rotation has a non-finite entry");
    if (!c.allFinite()) throw InvalidArgument("center has a non-finite entry");
    for (Eigen::Vector3d& v : mesh.vertices) v = rotation * (v - c) + c;
    transform_normals(mesh.vertex_normals, rotation);
    transform_normals(mesh.triangle_normals, rotation);
}

void scale(TriangleMesh& mesh, double factor, const Eigen::Vector3d& c) {
    if (!std::isfinite(factor)) throw InvalidArgument("scale is not finite");
    if (!c.allFinite()) throw InvalidArgument("center has a non-finite entry");
    for (Eigen::Vector3d& v : mesh.vertices) v = (v - c) * factor + c;
}

void paint_uniform_color(TriangleMesh& mesh, const Eigen::Vector3d& rgb) {
    if (!rgb.allFinite()) throw InvalidArgument("color has a non-finite entry");
    mesh.vertex_colors.assign(mesh.vertices.size(), rgb.cwiseMax(0.0).cwiseMin(1.0));
}

void compute_triangle_normals(TriangleMesh& mesh, bool normalized) {
    validate_triangles(mesh);
    const long long m = static_cast<long long>(mesh.triangles.size());
    std::vector<Eigen::Vector3d> normals(mesh.triangles.size());
#pragma omp parallel for schedule(static) num_threads(o3d::utility::resolve_num_threads()) if (m > kParallelTriangles)
    for (long long t = 0; t < m; ++t) {
        normals[t] = triangle_cross(mesh, static_cast<size_t>(t));
    }
    if (normalized) normalize_in_place(normals);
    mesh.triangle_normals = std::move(normals);
}

void compute_vertex_normals(TriangleMesh& mesh, bool normalized) {
    compute_triangle_normals(mesh, false);
    // A serial scatter in triangle order: the sums (and so the bits) do not depend on the thread count.
    std::vector<Eigen::Vector3d> sums(mesh.vertices.size(), Eigen::Vector3d::Zero());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        const Eigen::Vector3d& n = mesh.triangle_normals[t];
        sums[tri(0)] += n;
        sums[tri(1)] += n;
        sums[tri(2)] += n;
    }
    mesh.vertex_normals = std::move(sums);
    if (normalized) normalize_normals(mesh);
}

void normalize_normals(TriangleMesh& mesh) {
    normalize_in_place(mesh.vertex_normals);
    normalize_in_place(mesh.triangle_normals);
}

std::vector<double> triangle_areas(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    const long long m = static_cast<long long>(mesh.triangles.size());
    std::vector<double> areas(mesh.triangles.size());
#pragma omp parallel for schedule(static) num_threads(o3d::utility::resolve_num_threads()) if (m > kParallelTriangles)
    for (long long t = 0; t < m; ++t) areas[t] = triangle_area(mesh, static_cast<size_t>(t));
    return areas;
}

double surface_area(const TriangleMesh& mesh) {
    double total = 0.0;
    if (static_cast<long long>(mesh.triangles.size()) > kParallelTriangles && o3d::utility::resolve_num_threads() > 1) {
        for (const double a : triangle_areas(mesh)) total += a;  // the same sum, in the same order
        return total;
    }
    validate_triangles(mesh);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) total += triangle_area(mesh, t);
    return total;
}

}  // namespace o3d::geometry
