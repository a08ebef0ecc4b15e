// SPDX-License-Identifier: MIT
/// @file poisson_field.cpp
/// @brief Multi-depth normal field and its gradient right-hand sides.
#include "o3d/geometry/poisson_field.h"

#include <array>

#include "o3d/geometry/poisson_system.h"

namespace o3d::geometry::poisson {

namespace {

// 1D integrals over [0,1] of hats of width h, centres `off` cells apart; a hat on the domain boundary
// (side -1 low, +1 high) is cut in half.
double mass1(int off, int side) { return off == 0 ? (side ? 1.0 / 3.0 : 2.0 / 3.0) : 1.0 / 6.0; }  // /h
double cross1(int off, int side) {  // int B_{v+off} B_v'
    return off == 0 ? (side < 0 ? -0.5 : (side > 0 ? 0.5 : 0.0)) : (off > 0 ? -0.5 : 0.5);
}
int side_of(int c, int res) { return c == 0 ? -1 : (c == res ? 1 : 0); }

bool any_nonzero(const std::vector<Eigen::Vector3d>& f) {
    for (const auto& v : f)
        if (v.x() != 0 || v.y() != 0 || v.z() != 0) return true;
    return false;
}

}  // namespace

std::vector<Eigen::Vector3d> splat_field(const Level& L, const std::vector<Eigen::Vector3d>& u,
                                         const std::vector<Eigen::Vector3d>& area_normals,
                                         const std::vector<int8_t>& sample_depth) {
    std::vector<Eigen::Vector3d> field(L.keys.size() + 1, Eigen::Vector3d::Zero());
    const double inv_h3 = double(L.res) * L.res * L.res;
    for (size_t s = 0; s < u.size(); ++s) {
        if (sample_depth[s] != L.depth) continue;
        int c[3];
        double f[3], w[8];
        locate(u[s], L.res, c, f);
        corner_weights(f, w);
        for (int k = 0; k < 8; ++k) {
            const int64_t idx = L.find(pack(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1)));
            if (idx >= 0) field[size_t(idx)] += (w[k] * inv_h3) * area_normals[s];
        }
    }
    return field;
}

void add_prolonged_field(const Level& coarse, const std::vector<Eigen::Vector3d>& coarse_field, const Level& fine,
                         std::vector<Eigen::Vector3d>& fine_field, int threads) {
    const int64_t n = int64_t(fine.keys.size());
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < n; ++i)
        fine_field[size_t(i)] += prolonged_value(coarse, coarse_field, fine.keys[size_t(i)]);
}

namespace {

// <grad B_v, B_w> per axis for w = v + (dx,dy,dz), v on the sides (sx,sy,sz) of the domain, at depth `res`.
Eigen::Vector3d gradient_entry(int dx, int dy, int dz, int sx, int sy, int sz, int res) {
    const double h2 = 1.0 / (double(res) * res);
    return Eigen::Vector3d(h2 * cross1(dx, sx) * mass1(dy, sy) * mass1(dz, sz),
                           h2 * mass1(dx, sx) * cross1(dy, sy) * mass1(dz, sz),
                           h2 * mass1(dx, sx) * mass1(dy, sy) * cross1(dz, sz));
}

// Rows of a field that is non-zero on few keys, scattered from those keys (serially, in key order).
void add_sparse_field_rows(const Level& L, const std::vector<Eigen::Vector3d>& field, std::vector<double>& rhs) {
    for (size_t w = 0; w < L.keys.size(); ++w) {
        const Eigen::Vector3d& f = field[w];
        if (f.x() == 0 && f.y() == 0 && f.z() == 0) continue;
        const int x = key_x(L.keys[w]), y = key_y(L.keys[w]), z = key_z(L.keys[w]);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int X = x - dx, Y = y - dy, Z = z - dz;  // the row v with w = v + (dx,dy,dz)
                    if (X < 0 || Y < 0 || Z < 0 || X > L.res || Y > L.res || Z > L.res) continue;
                    const int64_t v = L.find(pack(X, Y, Z));
                    if (v < 0 || size_t(v) >= L.n_active) continue;
                    rhs[size_t(v)] += gradient_entry(dx, dy, dz, side_of(X, L.res), side_of(Y, L.res),
                                                     side_of(Z, L.res), L.res)
                                          .dot(f);
                }
    }
}

}  // namespace

void add_field_rows(const Level& L, const LevelSystem& S, const std::vector<Eigen::Vector3d>& field,
                    std::vector<double>& rhs, int threads) {
    std::array<Eigen::Vector3d, 27> interior;
    for (int o = 0; o < 27; ++o) interior[size_t(o)] = gradient_entry(o % 3 - 1, (o / 3) % 3 - 1, o / 9 - 1, 0, 0, 0, L.res);
    const int64_t n = int64_t(L.n_active);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < n; ++i) {
        const auto& row = S.nbr[size_t(i)];
        double acc = 0;
        if (S.variant[size_t(i)] == 0) {
            for (size_t o = 0; o < 27; ++o) acc += interior[o].dot(field[size_t(row[o])]);
        } else {  // a boundary row: its half hat integrates differently
            const Key k = L.keys[size_t(i)];
            const int sx = side_of(key_x(k), L.res), sy = side_of(key_y(k), L.res), sz = side_of(key_z(k), L.res);
            for (int o = 0; o < 27; ++o)
                acc += gradient_entry(o % 3 - 1, (o / 3) % 3 - 1, o / 9 - 1, sx, sy, sz, L.res)
                           .dot(field[size_t(row[size_t(o)])]);
        }
        rhs[size_t(i)] += acc;
    }
}

std::vector<std::vector<double>> deep_rhs(const std::vector<Level>& levels, const std::vector<Eigen::Vector3d>& u,
                                          const std::vector<Eigen::Vector3d>& area_normals,
                                          const std::vector<int8_t>& sample_depth, int threads) {
    const int depth = int(levels.size()) - 1;
    std::vector<char> has(levels.size(), 0);
    for (int8_t d : sample_depth) has[size_t(d)] = 1;
    std::vector<std::vector<double>> rhs(levels.size());
    for (int d = depth; d >= 0; --d) {
        const Level& L = levels[size_t(d)];
        rhs[size_t(d)] = d < depth ? restrict_rhs(levels[size_t(d) + 1], rhs[size_t(d) + 1], L, threads)
                                   : std::vector<double>(L.n_active, 0.0);
        if (has[size_t(d)]) add_sparse_field_rows(L, splat_field(L, u, area_normals, sample_depth), rhs[size_t(d)]);
    }
    return rhs;
}

void ShallowField::add_rows(const std::vector<Level>& levels, int d, const LevelSystem& S, std::vector<double>& rhs) {
    const Level& L = levels[size_t(d)];
    std::vector<Eigen::Vector3d> here(L.keys.size() + 1, Eigen::Vector3d::Zero());
    if (d > 0 && !carried_.empty()) {
        add_prolonged_field(levels[size_t(d) - 1], carried_, L, here, threads_);
        add_field_rows(L, S, here, rhs, threads_);
    }
    if (has_[size_t(d)]) {
        const std::vector<Eigen::Vector3d> own = splat_field(L, *u_, *area_normals_, *sample_depth_);
        for (size_t i = 0; i < here.size(); ++i) here[i] += own[i];
    }
    if (any_nonzero(here))
        carried_ = std::move(here);
    else
        carried_.clear();
}

ShallowField::ShallowField(int depth, const std::vector<Eigen::Vector3d>& u,
                           const std::vector<Eigen::Vector3d>& area_normals, const std::vector<int8_t>& sample_depth,
                           int threads)
    : u_(&u), area_normals_(&area_normals), sample_depth_(&sample_depth), threads_(threads),
      has_(size_t(depth) + 1, 0) {
    for (int8_t d : sample_depth) has_[size_t(d)] = 1;
}

}  // namespace o3d::geometry::poisson
