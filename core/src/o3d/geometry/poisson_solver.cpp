// SPDX-License-Identifier: MIT
/// @file poisson_solver.cpp
/// @brief Cascadic conjugate-gradient solve over the octree depths.
#include "o3d/geometry/poisson_solver.h"

#include "o3d/geometry/poisson_field.h"

#include <algorithm>
#include <cmath>

namespace o3d::geometry::poisson {

namespace {

// Threads for a loop of n cheap iterations: small loops run serially, where a parallel region's start-up and
// barrier would cost more than the work (and much more on an oversubscribed machine, where every barrier
// can wait a scheduler time slice for a descheduled thread).
int team(int threads, size_t n) { return n < 131072 ? 1 : threads; }

// Sum of a[i]*b[i] in fixed blocks combined in order: the result does not depend on the thread count.
double dot(const std::vector<double>& a, const std::vector<double>& b, size_t n, int threads) {
    constexpr size_t kBlock = 8192;
    const int64_t nb = int64_t((n + kBlock - 1) / kBlock);
    std::vector<double> part(size_t(nb), 0.0);
#pragma omp parallel for num_threads(team(threads, n)) schedule(static)
    for (int64_t blk = 0; blk < nb; ++blk) {
        double s = 0;
        const size_t e = std::min(n, size_t(blk + 1) * kBlock);
        for (size_t i = size_t(blk) * kBlock; i < e; ++i) s += a[i] * b[i];
        part[size_t(blk)] = s;
    }
    double s = 0;
    for (double p : part) s += p;
    return s;
}

// Jacobi-preconditioned CG on the active rows; x starts at 0. Vectors are sized keys+1 so the operator can
// read the one-ring (kept 0) and the dummy neighbour.
bool conjugate_gradient(const LevelSystem& S, size_t n, size_t full, const std::vector<double>& b,
                        std::vector<double>& x, int max_iters, double tol, int threads,
                        const std::function<bool()>& keep_going) {
    const std::vector<double> diag = operator_diagonal(S, n);
    std::vector<double> r(b.begin(), b.begin() + std::ptrdiff_t(n)), z(n), p(full, 0.0), q(n);
    std::vector<double> scratch(S.pt_weight.size());
    x.assign(n, 0.0);
    const int64_t nn = int64_t(n);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < nn; ++i) z[size_t(i)] = r[size_t(i)] / diag[size_t(i)];
    std::copy(z.begin(), z.end(), p.begin());
    double rz = dot(r, z, n, threads);
    const double r0 = std::sqrt(dot(r, r, n, threads));
    if (r0 == 0) return true;
    int it = 0;
    for (; it < max_iters; ++it) {
        if ((it & 7) == 7 && !keep_going()) return false;
        apply_operator(S, p.data(), q.data(), n, scratch.data(), team(threads, n));
        const double pq = dot(p, q, n, threads);
        if (!(pq > 0)) break;
        const double alpha = rz / pq;
        // One pass updates x, r, z and sums r.r and r.z over fixed blocks (thread-count independent).
        constexpr size_t kBlock = 8192;
        const int64_t nb = int64_t((n + kBlock - 1) / kBlock);
        std::vector<double> part_rr(static_cast<size_t>(nb)), part_rz(static_cast<size_t>(nb));
#pragma omp parallel for num_threads(team(threads, n)) schedule(static)
        for (int64_t blk = 0; blk < nb; ++blk) {
            double rr = 0, rzb = 0;
            const size_t e = std::min(n, size_t(blk + 1) * kBlock);
            for (size_t i = size_t(blk) * kBlock; i < e; ++i) {
                x[i] += alpha * p[i];
                r[i] -= alpha * q[i];
                z[i] = r[i] / diag[i];
                rr += r[i] * r[i];
                rzb += r[i] * z[i];
            }
            part_rr[size_t(blk)] = rr;
            part_rz[size_t(blk)] = rzb;
        }
        double rr = 0, rz_new = 0;
        for (int64_t blk = 0; blk < nb; ++blk) rr += part_rr[size_t(blk)], rz_new += part_rz[size_t(blk)];
        if (std::sqrt(rr) <= tol * r0) break;
        const double beta = rz_new / rz;
        rz = rz_new;
#pragma omp parallel for num_threads(team(threads, n)) schedule(static)
        for (int64_t i = 0; i < nn; ++i) p[size_t(i)] = z[size_t(i)] + beta * p[size_t(i)];
    }
    return true;
}

}  // namespace

std::vector<double> prolong(const Level& coarse, const Level& fine, int threads) {
    const int64_t n = int64_t(fine.keys.size());
    std::vector<double> y(size_t(n) + 1, 0.0);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < n; ++i) y[size_t(i)] = prolonged_value(coarse, coarse.y, fine.keys[size_t(i)]);
    return y;
}

bool solve_cascade(std::vector<Level>& levels, const CascadeInput& in) {
    const int depth = int(levels.size()) - 1;
    const int threads = in.threads;
    double total = 0, done = 0;
    for (const Level& L : levels) total += double(L.n_active);
    auto report = [&](double extra) { return !in.progress || in.progress(std::min(1.0, (done + extra) / total)); };

    std::vector<std::vector<double>> rhs = deep_rhs(levels, *in.u, *in.area_normals, *in.sample_depth, threads);
    ShallowField shallow(depth, *in.u, *in.area_normals, *in.sample_depth, threads);
    LevelSystem finest;
    assemble_level(levels[size_t(depth)], (*in.cells)[size_t(depth)], in.screening * std::ldexp(1.0, depth),
                   finest, threads);

    for (int d = 0; d <= depth; ++d) {
        Level& L = levels[size_t(d)];
        LevelSystem local;
        if (d < depth)
            assemble_level(L, (*in.cells)[size_t(d)], in.screening * std::ldexp(1.0, d), local, threads);
        const LevelSystem& S = d < depth ? local : finest;
        const size_t n = L.n_active;
        std::vector<double> y = d == 0 ? std::vector<double>(L.keys.size() + 1, 0.0)
                                       : prolong(levels[size_t(d) - 1], L, threads);
        // Residual of the coarser solution: b - A y'.
        std::vector<double> b = std::move(rhs[size_t(d)]);
        shallow.add_rows(levels, d, S, b);
        add_screening_target(S, in.target, b);
        {
            std::vector<double> ay(n), scratch(S.pt_weight.size());
            apply_operator(S, y.data(), ay.data(), n, scratch.data(), team(threads, n));
            for (size_t i = 0; i < n; ++i) b[i] -= ay[i];
        }
        // Complete coarse grids are cheap: solve them tightly so the global shape is right; the sparse
        // fine depths only add detail near the samples and converge in a few tens of iterations.
        const bool complete = n == size_t(L.res + 1) * size_t(L.res + 1) * size_t(L.res + 1);
        const int iters = complete ? 400 : 60;
        const double tol = complete ? 1e-8 : 1e-4;
        std::vector<double> x;
        if (!conjugate_gradient(S, n, L.keys.size() + 1, b, x, iters, tol, threads, [&] { return report(0); }))
            return false;
        for (size_t i = 0; i < n; ++i) y[i] += x[i];
        y.pop_back();
        L.y = std::move(y);
        done += double(n);
        if (!report(0)) return false;
    }
    return true;
}

}  // namespace o3d::geometry::poisson
