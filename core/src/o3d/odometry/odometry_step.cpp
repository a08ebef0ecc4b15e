// SPDX-License-Identifier: MIT
#include "o3d/odometry/odometry_step.h"

#include <cmath>

#include "o3d/odometry/odometry_reduce.h"
#include "o3d/odometry/odometry_sums.h"

namespace o3d::odometry::detail {
namespace {

constexpr double kSobelScale = 0.125;         // the 3 x 3 Sobel kernels sum |weights| to 8
constexpr double kHybridDepthWeight = 0.968;  // Park et al.'s lambda between the depth and intensity terms

/// @brief The rows of two correspondences at once, one per lane (Open3D's ComputeJacobianAndResidual for each
/// term): the photometric row, and with `kHybrid` the geometric row.
template <bool kHybrid>
struct Rows {
    double r[3][3], t[3];  // the motion
    double fx, fy;

    /// @brief `live` is 1 in a lane that holds a correspondence and 0 in one that only fills the pair.
    void add(const SourcePixel& s0, const TargetPixel& t0, const SourcePixel& s1, const TargetPixel& t1, Lanes live,
             LaneSums& sums) const {
        const Lanes x = lanes(s0.x, s1.x), y = lanes(s0.y, s1.y), z = lanes(s0.z, s1.z);
        Lanes p[3];
        for (int i = 0; i < 3; ++i) p[i] = ((splat(r[i][0]) * x + splat(r[i][1]) * y) + splat(r[i][2]) * z) + t[i];
        const Lanes inv_z = 1.0 / p[2];
        const double w_img = kHybrid ? std::sqrt(1.0 - kHybridDepthWeight) : 1.0;
        // Photometric row: the target's intensity gradient through the projection's derivative.
        const Lanes diff = lanes(t0.intensity, t1.intensity) - lanes(s0.intensity, s1.intensity);
        const Lanes c0 = kSobelScale * lanes(t0.dx, t1.dx) * fx * inv_z;
        const Lanes c1 = kSobelScale * lanes(t0.dy, t1.dy) * fy * inv_z;
        const Lanes c2 = -(c0 * p[0] + c1 * p[1]) * inv_z;
        const Lanes w = w_img * live;
        const Lanes j_img[6] = {w * (-p[2] * c1 + p[1] * c2), w * (p[2] * c0 - p[0] * c2), w * (-p[1] * c0 + p[0] * c1),
                                w * c0, w * c1, w * c2};
        if constexpr (!kHybrid) {
            sums.add(j_img, w * diff);
        } else {
            // Geometric row: the target's depth against the moved point's depth.
            const Lanes w_dep = std::sqrt(kHybridDepthWeight) * live;
            const Lanes diff_geo = lanes(t0.depth, t1.depth) - p[2];
            const Lanes d0 = kSobelScale * lanes(t0.ddx, t1.ddx) * fx * inv_z;
            const Lanes d1 = kSobelScale * lanes(t0.ddy, t1.ddy) * fy * inv_z;
            const Lanes d2 = -(d0 * p[0] + d1 * p[1]) * inv_z;
            const Lanes j_dep[6] = {w_dep * ((-p[2] * d1 + p[1] * d2) - p[1]),
                                    w_dep * ((p[2] * d0 - p[0] * d2) + p[0]),
                                    w_dep * (-p[1] * d0 + p[0] * d1),
                                    w_dep * d0,
                                    w_dep * d1,
                                    w_dep * (d2 - 1.0)};
            sums.add(j_img, w * diff, j_dep, w_dep * diff_geo);
        }
    }
};

/// @brief One block's share: its lanes are added and converted to NormalEquations6's layout when the block ends.
struct Partial {
    registration::detail::NormalEquations6 equations;
    size_t correspondences = 0;
    Partial& operator+=(const Partial& o) {
        equations.add(o.equations);
        correspondences += o.correspondences;
        return *this;
    }
};

template <bool kHybrid>
StepSums sums_for(const PackedLevel& level, const Eigen::Matrix4d& motion, double depth_diff_max) {
    const Warp warp(level.camera, motion);
    Rows<kHybrid> rows{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) rows.r[i][j] = motion(i, j);
        rows.t[i] = motion(i, 3);
    }
    rows.fx = level.camera.fx;
    rows.fy = level.camera.fy;
    const Partial total = reduce_row_blocks<Partial>(level.camera.height, [&](int first, int last, Partial& out) {
        LaneSums sums;
        size_t count = 0;
        std::vector<Match> matches;
        visit_matches(level, warp, depth_diff_max, first, last, matches,
                      [&](const SourcePixel* row, const Match* m, size_t n) {
                          size_t k = 0;
                          for (; k + 1 < n; k += 2)
                              rows.add(row[m[k].u_s], level.target_at(m[k].u_t, m[k].v_t), row[m[k + 1].u_s],
                                       level.target_at(m[k + 1].u_t, m[k + 1].v_t), splat(1.0), sums);
                          if (k < n) {  // an odd one out: the second lane repeats it with weight 0
                              const SourcePixel& s = row[m[k].u_s];
                              const TargetPixel& t = level.target_at(m[k].u_t, m[k].v_t);
                              rows.add(s, t, s, t, lanes(1.0, 0.0), sums);
                          }
                          count += n;
                      });
        out = {sums.equations(), count};
    });
    return {total.equations, total.correspondences};
}

}  // namespace

StepSums step_sums(const PackedLevel& level, const Eigen::Matrix4d& motion, Jacobian jacobian, double depth_diff_max) {
    return jacobian == Jacobian::HybridTerm ? sums_for<true>(level, motion, depth_diff_max)
                                            : sums_for<false>(level, motion, depth_diff_max);
}

}  // namespace o3d::odometry::detail
