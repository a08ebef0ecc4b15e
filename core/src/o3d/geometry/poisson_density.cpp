// SPDX-License-Identifier: MIT
/// @file poisson_density.cpp
/// @brief Multi-depth hat splats and the density-as-depth estimate.
#include "o3d/geometry/poisson_density.h"

#include <cmath>

#include "o3d/geometry/poisson_system.h"

namespace o3d::geometry::poisson {

void LevelSplat::build(const std::vector<Eigen::Vector3d>& u, const std::vector<double>& values, int channels,
                       int depth) {
    stride_ = channels + 1;
    levels_.assign(size_t(depth) + 1, Grid());
    {
        Grid& G = levels_[size_t(depth)];
        const int res = 1 << depth;
        for (const auto& p : u) {
            int c[3];
            double f[3];
            locate(p, res, c, f);
            for (int k = 0; k < 8; ++k) G.keys.push_back(pack(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1)));
        }
        sort_unique(G.keys);
        G.index.build(G.keys);
        G.data.assign(G.keys.size() * size_t(stride_), 0.0);
        for (size_t s = 0; s < u.size(); ++s) {
            int c[3];
            double f[3], w[8];
            locate(u[s], res, c, f);
            corner_weights(f, w);
            for (int k = 0; k < 8; ++k) {
                const int64_t idx =
                    G.index.find(G.keys.data(), pack(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1)));
                double* dst = &G.data[size_t(idx) * size_t(stride_)];
                dst[0] += w[k];
                for (int ch = 0; ch < channels; ++ch) dst[1 + ch] += w[k] * values[s * size_t(channels) + size_t(ch)];
            }
        }
    }
    // A coarse hat is the fine hats at the even vertex (weight 1) and at the odd neighbours (weight 1/2),
    // so the coarse splat is the same combination of the fine one.
    for (int d = depth; d > 0; --d) {
        const Grid& F = levels_[size_t(d)];
        Grid& C = levels_[size_t(d) - 1];
        C.keys = coarsen(F.keys, 0, 1 << (d - 1));
        C.index.build(C.keys);
        C.data.assign(C.keys.size() * size_t(stride_), 0.0);
        for (size_t i = 0; i < F.keys.size(); ++i) {
            const Key k = F.keys[i];
            const int c[3] = {key_x(k), key_y(k), key_z(k)};
            int lo[3], hi[3];
            for (int a = 0; a < 3; ++a) lo[a] = c[a] >> 1, hi[a] = (c[a] + 1) >> 1;
            for (int z = lo[2]; z <= hi[2]; ++z)
                for (int y = lo[1]; y <= hi[1]; ++y)
                    for (int x = lo[0]; x <= hi[0]; ++x) {
                        const double w = (lo[0] == hi[0] ? 1.0 : 0.5) * (lo[1] == hi[1] ? 1.0 : 0.5) *
                                         (lo[2] == hi[2] ? 1.0 : 0.5);
                        const int64_t idx = C.index.find(C.keys.data(), pack(x, y, z));
                        double* dst = &C.data[size_t(idx) * size_t(stride_)];
                        for (int ch = 0; ch < stride_; ++ch) dst[ch] += w * F.data[i * size_t(stride_) + size_t(ch)];
                    }
        }
    }
}

void LevelSplat::eval(const Eigen::Vector3d& u, int d, double* out) const {
    const Grid& G = levels_[size_t(d)];
    int c[3];
    double f[3], w[8];
    locate(u, 1 << d, c, f);
    corner_weights(f, w);
    for (int ch = 0; ch < stride_; ++ch) out[ch] = 0;
    for (int k = 0; k < 8; ++k) {
        if (w[k] == 0) continue;
        const int64_t idx = G.index.find(G.keys.data(), pack(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1)));
        if (idx < 0) continue;
        for (int ch = 0; ch < stride_; ++ch) out[ch] += w[k] * G.data[size_t(idx) * size_t(stride_) + size_t(ch)];
    }
}

double density_depth(const LevelSplat& splat, const Eigen::Vector3d& u) {
    // On a plane sampled with rho samples per unit area the kernel density at depth d averages
    // (2/3) rho 4^-d, so one sample per cell (rho 4^-d = 1) is a kernel density of 2/3.
    constexpr double kPerCell = 1.5;
    // PoissonRecon's values (Open3D 0.20.0 on uniformly sampled spheres and tori, see
    // tools/reference/record_poisson.py) sit this many depths below log4(samples per unit area).
    constexpr double kOffset = -0.33;
    double out[8];  // channels() <= 7 (callers splat at most a colour)
    for (int d = splat.depth(); d >= 0; --d) {
        splat.eval(u, d, out);
        const double n = kPerCell * out[0];
        if (n >= 1.0 || (d == 0 && n > 0)) return d + std::log(n) / std::log(4.0) + kOffset;
    }
    return 0.0;
}

}  // namespace o3d::geometry::poisson
