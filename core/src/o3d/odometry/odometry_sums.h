// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_sums.h
/// @brief J^T J and J^T r of six-parameter rows that arrive two at a time, one per vector lane: the odometry pass
/// works on two correspondences at once, so each instruction does two correspondences' arithmetic.
#include "o3d/registration/estimation_point_to_plane.h"

namespace o3d::odometry::detail {

/// @brief Two doubles in one register (GCC/Clang vector extensions: SSE2 on x86-64, NEON on ARM, scalar code
/// elsewhere). Arithmetic is per lane and IEEE, the same as on scalars.
typedef double Lanes __attribute__((vector_size(2 * sizeof(double))));

inline Lanes lanes(double a, double b) { return Lanes{a, b}; }
inline Lanes splat(double a) { return Lanes{a, a}; }

/// @brief Each lane is its own NormalEquations6 (upper triangle row-major, and J^T r); equations() adds lane 1
/// to lane 0 at the end.
class LaneSums {
public:
    /// @brief add_row(j, r, 1) in each lane.
    void add(const Lanes j[6], Lanes r) {
        int k = 0;
#pragma GCC unroll 6
        for (int a = 0; a < 6; ++a) {
#pragma GCC unroll 6
            for (int b = a; b < 6; ++b) jtj_[k++] += j[a] * j[b];
            jtr_[a] += j[a] * r;
        }
    }
    /// @brief add_row(x, rx, 1) then add_row(y, ry, 1) in each lane, with one load and store of each sum.
    void add(const Lanes x[6], Lanes rx, const Lanes y[6], Lanes ry) {
        int k = 0;
#pragma GCC unroll 6
        for (int a = 0; a < 6; ++a) {
#pragma GCC unroll 6
            for (int b = a; b < 6; ++b, ++k) jtj_[k] = (jtj_[k] + x[a] * x[b]) + y[a] * y[b];
            jtr_[a] = (jtr_[a] + x[a] * rx) + y[a] * ry;
        }
    }
    registration::detail::NormalEquations6 equations() const {
        registration::detail::NormalEquations6 out;
        for (int k = 0; k < 21; ++k) out.jtj[k] = jtj_[k][0] + jtj_[k][1];
        for (int k = 0; k < 6; ++k) out.jtr[k] = jtr_[k][0] + jtr_[k][1];
        return out;
    }

private:
    Lanes jtj_[21] = {};
    Lanes jtr_[6] = {};
};

}  // namespace o3d::odometry::detail
