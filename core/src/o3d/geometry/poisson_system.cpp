// SPDX-License-Identifier: MIT
/// @file poisson_system.cpp
/// @brief Assembly of the per-depth screened-Poisson systems in the trilinear hat basis.
#include "o3d/geometry/poisson_system.h"

#include <algorithm>

#include "o3d/geometry/radix_sort.h"

namespace o3d::geometry::poisson {

namespace {

// 1D integrals over [0,1] of hats of width h, centres `off` cells apart, divided by the powers of h they
// carry. Only a hat on the domain boundary (side: -1 low, +1 high, 0 inside) is cut in half, and only its
// product with itself changes.
double mass1(int off, int side = 0) { return off == 0 ? (side ? 1.0 / 3.0 : 2.0 / 3.0) : 1.0 / 6.0; }  // /h
double stiff1(int off, int side = 0) { return off == 0 ? (side ? 1.0 : 2.0) : -1.0; }                  // *h
int side_of(int c, int res) { return c == 0 ? -1 : (c == res ? 1 : 0); }

int offset_index(int dx, int dy, int dz) { return (dx + 1) + 3 * (dy + 1) + 9 * (dz + 1); }

CellSamples group(std::vector<std::pair<uint64_t, size_t>>& items, const std::vector<double>& w,
                  const std::vector<Eigen::Vector3d>& p) {
    radix_sort_by_key(items, 3 * kKeyBits);
    CellSamples out;
    for (size_t i = 0; i < items.size();) {
        size_t j = i;
        double sw = 0;
        Eigen::Vector3d sp = Eigen::Vector3d::Zero();
        for (; j < items.size() && items[j].first == items[i].first; ++j) {
            sw += w[items[j].second];
            sp += w[items[j].second] * p[items[j].second];
        }
        out.cell.push_back(items[i].first);
        out.weight.push_back(sw);
        out.mean.push_back(sw > 0 ? Eigen::Vector3d(sp / sw) : p[items[i].second]);
        i = j;
    }
    return out;
}

}  // namespace

CellSamples aggregate_samples(const std::vector<Eigen::Vector3d>& u, int depth) {
    const int res = 1 << depth;
    std::vector<std::pair<uint64_t, size_t>> items(u.size());
    for (size_t i = 0; i < u.size(); ++i) {
        int c[3];
        double f[3];
        locate(u[i], res, c, f);
        items[i] = {pack(c[0], c[1], c[2]), i};
    }
    return group(items, std::vector<double>(u.size(), 1.0), u);
}

CellSamples aggregate_parents(const CellSamples& fine) {
    std::vector<std::pair<uint64_t, size_t>> items(fine.cell.size());
    for (size_t i = 0; i < items.size(); ++i) {
        const Key k = fine.cell[i];
        items[i] = {pack(key_x(k) >> 1, key_y(k) >> 1, key_z(k) >> 1), i};
    }
    return group(items, fine.weight, fine.mean);
}

void assemble_level(const Level& L, const CellSamples& cells, double beta, LevelSystem& S, int threads) {
    S.h = 1.0 / L.res;
    S.beta = beta;
    for (int var = 0; var < 8; ++var) {
        const int sx = var & 1, sy = (var >> 1) & 1, sz = (var >> 2) & 1;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    S.stencil[size_t(var)][size_t(offset_index(dx, dy, dz))] =
                        S.h * (stiff1(dx, sx) * mass1(dy, sy) * mass1(dz, sz) +
                               mass1(dx, sx) * stiff1(dy, sy) * mass1(dz, sz) +
                               mass1(dx, sx) * mass1(dy, sy) * stiff1(dz, sz));
    }
    const int32_t dummy = int32_t(L.keys.size());
    const int64_t n = int64_t(L.n_active);
    S.nbr.resize(size_t(n));
    S.variant.resize(size_t(n));
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < n; ++i) {
        const Key k = L.keys[size_t(i)];
        const int x = key_x(k), y = key_y(k), z = key_z(k);
        S.variant[size_t(i)] = uint8_t((side_of(x, L.res) ? 1 : 0) | (side_of(y, L.res) ? 2 : 0) |
                                       (side_of(z, L.res) ? 4 : 0));
        auto& row = S.nbr[size_t(i)];
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int X = x + dx, Y = y + dy, Z = z + dz;
                    int64_t idx = -1;
                    if (X >= 0 && Y >= 0 && Z >= 0 && X <= L.res && Y <= L.res && Z <= L.res)
                        idx = L.find(pack(X, Y, Z));
                    row[size_t(offset_index(dx, dy, dz))] = idx < 0 ? dummy : int32_t(idx);
                }
    }
    const size_t np = cells.cell.size();
    S.pt_weight.resize(np);
    S.pt_bw.resize(np);
    S.pt_corner.resize(np);
    S.cell_point.assign(L.keys.size() + 1, -1);
    for (size_t p = 0; p < np; ++p) {
        const Key c = cells.cell[p];
        const int cx = key_x(c), cy = key_y(c), cz = key_z(c);
        double f[3];
        for (int a = 0; a < 3; ++a) {
            const int ca = a == 0 ? cx : (a == 1 ? cy : cz);
            f[a] = std::min(std::max(cells.mean[p][a] * L.res - ca, 0.0), 1.0);
        }
        corner_weights(f, S.pt_bw[p].data());
        S.pt_weight[p] = beta * cells.weight[p];
        for (int k = 0; k < 8; ++k) {
            const int64_t idx = L.find(pack(cx + (k & 1), cy + ((k >> 1) & 1), cz + ((k >> 2) & 1)));
            S.pt_corner[p][size_t(k)] = idx < 0 ? dummy : int32_t(idx);
        }
        const int64_t base = L.find(c);
        if (base >= 0) S.cell_point[size_t(base)] = int32_t(p);
    }
}

std::vector<double> restrict_rhs(const Level& fine, const std::vector<double>& fine_rhs, const Level& coarse,
                                 int threads) {
    const int64_t n = int64_t(coarse.n_active);
    std::vector<double> out(size_t(n), 0.0);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < n; ++i) {
        const Key k = coarse.keys[size_t(i)];
        const int x = 2 * key_x(k), y = 2 * key_y(k), z = 2 * key_z(k);
        double acc = 0;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int X = x + dx, Y = y + dy, Z = z + dz;
                    if (X < 0 || Y < 0 || Z < 0 || X > fine.res || Y > fine.res || Z > fine.res) continue;
                    const int64_t idx = fine.find(pack(X, Y, Z));
                    if (idx < 0 || size_t(idx) >= fine.n_active) continue;
                    const double w = (dx ? 0.5 : 1.0) * (dy ? 0.5 : 1.0) * (dz ? 0.5 : 1.0);
                    acc += w * fine_rhs[size_t(idx)];
                }
        out[size_t(i)] = acc;
    }
    return out;
}

void apply_operator(const LevelSystem& S, const double* z, double* out, size_t n_active, double* scratch,
                    int threads) {
    const int64_t np = int64_t(S.pt_weight.size());
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static)
        for (int64_t p = 0; p < np; ++p) {
            double v = 0;
            for (size_t k = 0; k < 8; ++k) v += S.pt_bw[size_t(p)][k] * z[S.pt_corner[size_t(p)][k]];
            scratch[p] = v;
        }
#pragma omp for schedule(static)
        for (int64_t i = 0; i < int64_t(n_active); ++i) {
            const auto& row = S.nbr[size_t(i)];
            const auto& st = S.stencil[S.variant[size_t(i)]];
            double acc = 0;
            for (size_t o = 0; o < 27; ++o) acc += st[o] * z[row[o]];
            // Screening: the row's vertex is corner (a,b,c) of the cell whose minimum corner is v-(a,b,c).
            for (int k = 0; k < 8; ++k) {
                const int a = k & 1, b = (k >> 1) & 1, c = (k >> 2) & 1;
                const int32_t cp = S.cell_point[size_t(row[size_t(13 - a - 3 * b - 9 * c)])];
                if (cp >= 0) acc += S.pt_weight[size_t(cp)] * S.pt_bw[size_t(cp)][size_t(k)] * scratch[cp];
            }
            out[i] = acc;
        }
    }
}

void add_screening_target(const LevelSystem& S, double target, std::vector<double>& rhs) {
    for (size_t p = 0; p < S.pt_weight.size(); ++p)
        for (size_t k = 0; k < 8; ++k) {
            const size_t c = size_t(S.pt_corner[p][k]);
            if (c < rhs.size()) rhs[c] += S.pt_weight[p] * S.pt_bw[p][k] * target;
        }
}

std::vector<double> operator_diagonal(const LevelSystem& S, size_t n_active) {
    std::vector<double> d(n_active);
    for (size_t i = 0; i < n_active; ++i) d[i] = S.stencil[S.variant[i]][13];
    for (size_t p = 0; p < S.pt_weight.size(); ++p)
        for (size_t k = 0; k < 8; ++k) {
            const size_t c = size_t(S.pt_corner[p][k]);
            if (c < n_active) d[c] += S.pt_weight[p] * S.pt_bw[p][k] * S.pt_bw[p][k];
        }
    return d;
}

}  // namespace o3d::geometry::poisson
