// SPDX-License-Identifier: MIT
/// @file poisson_reconstruction.cpp
/// @brief Screened Poisson reconstruction: input checks, normalisation to the unit cube, density-weighted
/// normal field, cascadic solve, iso-value, extraction, per-vertex densities and colours.
///
/// Basis: trilinear hats (degree-1 B-splines) centred on the octree's grid vertices rather than the paper's
/// degree-2 splines on cell centres. They are refinable (the two-scale relation used by the cascade), need a
/// 27-point stencil instead of 125, and make chi exactly trilinear on every finest cell, so marching cubes
/// reads chi at cell corners and the linear edge root is exact; near the samples the finest depth carries
/// the detail, and the accuracy tests bound the error well under a cell.
#include "o3d/geometry/poisson_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/geometry/poisson_density.h"
#include "o3d/geometry/poisson_extraction.h"
#include "o3d/geometry/poisson_octree.h"
#include "o3d/geometry/poisson_solver.h"
#include "o3d/geometry/poisson_system.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

namespace {

using namespace poisson;

constexpr int kMaxDepth = 16;
// Depths up to this are complete grids (17^3 vertices at most), solved tightly: they fix the global
// inside/outside. Deeper depths follow the samples and converge in a few iterations.
constexpr int kFullDepth = 4;
// Finest active vertices: the sample cells' corners grown by this many vertices (the normal field's
// divergence reaches exactly one ring, so every non-zero row of the finest system is kept).
constexpr int kFineDilation = 1;
constexpr int kCoarseDilation = 1;
// A sample is splatted this many depths below its density depth (PoissonRecon's density values, see
// poisson_density.h, sit about one depth under the depth its octree reaches).
constexpr double kSampleDepthOffset = 1.0;

void validate(const PointCloud& cloud, const PoissonOptions& o) {
    if (cloud.points.empty()) throw InvalidArgument("create_from_point_cloud_poisson: the point cloud is empty");
    if (!cloud.has_normals())
        throw InvalidArgument("create_from_point_cloud_poisson: the point cloud has no normals");
    for (size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite() || !cloud.normals[i].allFinite())
            throw InvalidArgument("create_from_point_cloud_poisson: point or normal " + std::to_string(i) +
                                  " is not finite");
    if (o.depth < 1 || o.depth > kMaxDepth)
        throw InvalidArgument("create_from_point_cloud_poisson: depth must be in [1, 16], got " +
                              std::to_string(o.depth));
    if (!std::isfinite(o.width) || o.width < 0)
        throw InvalidArgument("create_from_point_cloud_poisson: width must be finite and >= 0");
    if (!std::isfinite(o.scale) || o.scale <= 0)
        throw InvalidArgument("create_from_point_cloud_poisson: scale must be finite and > 0");
    if (!std::isfinite(o.point_weight) || o.point_weight < 0)
        throw InvalidArgument("create_from_point_cloud_poisson: point_weight must be finite and >= 0");
}

}  // namespace

PoissonResult create_from_point_cloud_poisson(const PointCloud& cloud, const PoissonOptions& options) {
    validate(cloud, options);
    const int threads = utility::resolve_num_threads(options.num_threads);
    auto check = [&](double f) {
        if (options.progress && !options.progress(std::min(std::max(f, 0.0), 1.0)))
            throw Cancelled("create_from_point_cloud_poisson: cancelled");
    };
    check(0.0);

    // The reconstruction cube: `scale` times the samples' bounding cube, same centre.
    Eigen::Vector3d lo = cloud.points[0], hi = cloud.points[0];
    for (const auto& p : cloud.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Eigen::Vector3d center = 0.5 * (lo + hi);
    double side = options.scale * (hi - lo).maxCoeff();
    if (!(side > 0) || !std::isfinite(side)) side = 1.0;  // a single position: any cube around it will do
    int depth = options.depth;
    if (options.width > 0) {
        // As PoissonRecon: the depth whose cells are no wider than `width`, and the cube grown to match.
        const double levels = std::ceil(std::log2(side / options.width));
        if (!(levels <= kMaxDepth))
            throw InvalidArgument("create_from_point_cloud_poisson: width " + std::to_string(options.width) +
                                  " needs a depth above 16");
        depth = std::max(1, int(levels));
        side = options.width * std::ldexp(1.0, depth);
    }
    const Eigen::Vector3d origin = center - Eigen::Vector3d::Constant(0.5 * side);
    const size_t n = cloud.points.size();
    std::vector<Eigen::Vector3d> u(n), normals(n);
    for (size_t i = 0; i < n; ++i) {
        u[i] = (cloud.points[i] - origin) / side;
        const double len = cloud.normals[i].norm();
        normals[i] = len > 0 ? Eigen::Vector3d(cloud.normals[i] / len) : Eigen::Vector3d::Zero();
    }

    // Sampling density at the kernel depth (two above the finest, as PoissonRecon): each sample stands
    // for the surface area around it, so sparse regions get as much normal field as dense ones.
    const int kernel_depth = std::max(0, depth - 2);
    LevelSplat density;
    density.build(u, {}, 0, kernel_depth);
    std::vector<Eigen::Vector3d> area_normals(n);
    double total_area = 0;
    {
        const double cell_area = std::ldexp(1.0, -2 * kernel_depth);
        for (size_t i = 0; i < n; ++i) {
            double w;
            density.eval(u[i], kernel_depth, &w);
            const double area = (2.0 / 3.0) * cell_area / std::max(w, 1e-12);
            area_normals[i] = area * normals[i];
            total_area += area;
        }
    }
    check(0.02);

    // Each sample's depth: as deep as its sampling density supports (about one sample per cell, one depth
    // finer, as PoissonRecon's octree goes), so that sparse scans are not refined into noise and
    // empty fine cells; never coarser than the complete grids, never finer than `depth`.
    const int full_depth = std::min(depth, kFullDepth);
    std::vector<int8_t> sample_depth(n);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i) {
        const double sd = std::floor(density_depth(density, u[size_t(i)]) + kSampleDepthOffset);
        sample_depth[size_t(i)] = int8_t(std::min(double(depth), std::max(double(full_depth), sd)));
    }
    std::vector<CellSamples> cells(size_t(depth) + 1);
    cells[size_t(depth)] = aggregate_samples(u, depth);
    for (int d = depth; d > 0; --d) cells[size_t(d) - 1] = aggregate_parents(cells[size_t(d)]);
    // Seeds: the corners of each sample's cell at its depth.
    std::vector<std::vector<Key>> seeds(size_t(depth) + 1);
    for (size_t i = 0; i < n; ++i) {
        const int d = sample_depth[i];
        int c[3];
        double f[3];
        locate(u[i], 1 << d, c, f);
        for (int k = 0; k < 8; ++k)
            seeds[size_t(d)].push_back(pack(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1)));
    }
    for (auto& s : seeds) sort_unique(s);
    std::vector<Level> levels = build_levels(std::move(seeds), depth, full_depth, kFineDilation, kCoarseDilation);
    check(0.05);

    CascadeInput in;
    in.u = &u;
    in.area_normals = &area_normals;
    in.cells = &cells;
    in.sample_depth = &sample_depth;
    // alpha * Area / sum of sample weights (the paper's normalisation; the cascade doubles it per depth).
    in.screening = options.point_weight * total_area / double(n);
    in.target = 0.5;
    in.threads = threads;
    in.progress = [&](double f) { return !options.progress || options.progress(0.05 + 0.75 * f); };
    if (!solve_cascade(levels, in)) throw Cancelled("create_from_point_cloud_poisson: cancelled");
    check(0.8);

    // Iso-value: the mean of chi over the samples, in fixed blocks so it is thread-count independent.
    const FunctionEvaluator chi(levels);
    double iso = 0;
    {
        constexpr size_t kBlock = 4096;
        const int64_t nb = int64_t((n + kBlock - 1) / kBlock);
        std::vector<double> part(size_t(nb), 0.0);
#pragma omp parallel for num_threads(threads) schedule(static)
        for (int64_t b = 0; b < nb; ++b) {
            double s = 0;
            for (size_t i = size_t(b) * kBlock; i < std::min(n, size_t(b + 1) * kBlock); ++i) s += chi.at(u[i]);
            part[size_t(b)] = s;
        }
        for (double p : part) iso += p;
        iso /= double(n);
    }

    IsoSurface surface;
    if (!extract_iso_surface(levels, chi, iso, std::min(depth, kFullDepth), surface,
                             [&] { return !options.progress || options.progress(0.85); }, threads,
                             options.close_boundary))
        throw Cancelled("create_from_point_cloud_poisson: cancelled");
    std::vector<Level>().swap(levels);
    check(0.95);

    PoissonResult result;
    const int64_t nv = int64_t(surface.vertices.size());
    result.mesh.vertices.resize(size_t(nv));
    result.densities.resize(size_t(nv));
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < nv; ++i) {
        result.mesh.vertices[size_t(i)] = origin + side * surface.vertices[size_t(i)];
        result.densities[size_t(i)] = density_depth(density, surface.vertices[size_t(i)]);
    }
    if (cloud.has_colors()) {
        // Colours splatted at the finest depth; where no sample reaches, the coarser splats take over.
        std::vector<double> rgb(3 * n);
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) rgb[3 * i + size_t(c)] = cloud.colors[i][c];
        LevelSplat colors;
        colors.build(u, rgb, 3, depth);
        result.mesh.vertex_colors.resize(size_t(nv));
#pragma omp parallel for num_threads(threads) schedule(static)
        for (int64_t i = 0; i < nv; ++i) {
            double out[4] = {0, 0, 0, 0};
            for (int d = depth; d >= 0; --d) {
                colors.eval(surface.vertices[size_t(i)], d, out);
                if (out[0] > 1e-6) break;
            }
            result.mesh.vertex_colors[size_t(i)] =
                out[0] > 0 ? Eigen::Vector3d(Eigen::Vector3d(out[1], out[2], out[3]) / out[0]) : Eigen::Vector3d::Zero();
        }
    }
    result.mesh.triangles = std::move(surface.triangles);
    check(1.0);
    return result;
}

}  // namespace o3d::geometry
