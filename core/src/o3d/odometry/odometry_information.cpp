// SPDX-License-Identifier: MIT
#include "o3d/odometry/odometry_information.h"

#include "o3d/odometry/odometry_reduce.h"

namespace o3d::odometry::detail {
namespace {

/// @brief Each correspondence adds g g^T for the three rows g = (-[q]x row i, e_i) at the target point q. Most
/// entries of those products are 0 or 1, so only the ten distinct sums are kept, a correspondence's terms added
/// in the order its three outer products would add them.
struct Moments {
    double xx_yy = 0, xx_zz = 0, yy_zz = 0, xy = 0, xz = 0, yz = 0, x = 0, y = 0, z = 0, n = 0;

    void add(double qx, double qy, double qz) {
        yy_zz += qz * qz;  // (0,0): rows 2 and 3
        yy_zz += qy * qy;
        xx_zz += qz * qz;  // (1,1): rows 1 and 3
        xx_zz += qx * qx;
        xx_yy += qy * qy;  // (2,2): rows 1 and 2
        xx_yy += qx * qx;
        xy += qy * -qx;
        xz += -qz * qx;
        yz += qz * -qy;
        x += qx;
        y += qy;
        z += qz;
        n += 1;
    }
    Moments& operator+=(const Moments& o) {
        xx_yy += o.xx_yy, xx_zz += o.xx_zz, yy_zz += o.yy_zz, xy += o.xy, xz += o.xz, yz += o.yz;
        x += o.x, y += o.y, z += o.z, n += o.n;
        return *this;
    }
};

}  // namespace

Matrix6d information_matrix(const PackedLevel& full, const Eigen::Matrix4d& motion, double depth_diff_max) {
    const LevelCamera& c = full.camera;
    const Warp warp(c, motion);
    const Moments m = reduce_row_blocks<Moments>(c.height, [&](int first, int last, Moments& out) {
        std::vector<Match> matches;
        visit_matches(full, warp, depth_diff_max, first, last, matches,
                      [&](const SourcePixel*, const Match* m, size_t n) {
                          for (size_t k = 0; k < n; ++k) {
                              // The target point as Open3D's float point image holds it.
                              const float d = full.target_at(m[k].u_t, m[k].v_t).depth;
                              out.add(float((m[k].u_t - c.cx) * d / c.fx), float((m[k].v_t - c.cy) * d / c.fy), d);
                          }
                      });
    });
    Matrix6d gtg = Matrix6d::Zero();
    gtg(0, 0) = m.yy_zz;
    gtg(1, 1) = m.xx_zz;
    gtg(2, 2) = m.xx_yy;
    gtg(0, 1) = gtg(1, 0) = m.xy;
    gtg(0, 2) = gtg(2, 0) = m.xz;
    gtg(1, 2) = gtg(2, 1) = m.yz;
    // Rotation against translation: the -[q]x entries.
    gtg(0, 4) = gtg(4, 0) = -m.z;
    gtg(0, 5) = gtg(5, 0) = m.y;
    gtg(1, 3) = gtg(3, 1) = m.z;
    gtg(1, 5) = gtg(5, 1) = -m.x;
    gtg(2, 3) = gtg(3, 2) = -m.y;
    gtg(2, 4) = gtg(4, 2) = m.x;
    gtg(3, 3) = gtg(4, 4) = gtg(5, 5) = m.n;
    return gtg;
}

}  // namespace o3d::odometry::detail
