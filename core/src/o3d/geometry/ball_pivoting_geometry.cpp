// SPDX-License-Identifier: MIT
#include "o3d/geometry/ball_pivoting_geometry.h"

#include <Eigen/Geometry>
#include <cmath>

namespace o3d::geometry::ball_pivoting {

bool ball_center(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, double radius2,
                 Eigen::Vector3d& center) {
    const Eigen::Vector3d u = p1 - p0;
    const Eigen::Vector3d v = p2 - p0;
    const Eigen::Vector3d w = u.cross(v);
    const double u2 = u.squaredNorm();
    const double v2 = v.squaredNorm();
    const double w2 = w.squaredNorm();
    // |w|^2 = |u|^2 |v|^2 sin^2(angle): below this the circumcentre is numerically meaningless.
    if (!(w2 > 1e-20 * u2 * v2) || w2 == 0.0) return false;
    // Circumcentre relative to p0, from the standard closed form (u x v is the plane normal).
    const Eigen::Vector3d offset = (u2 * v.cross(w) + v2 * w.cross(u)) / (2.0 * w2);
    double h2 = radius2 - offset.squaredNorm();
    // A ball exactly as large as the circumcircle (regular grids) must not be lost to rounding.
    if (h2 < 0.0) {
        if (h2 < -1e-12 * radius2) return false;
        h2 = 0.0;
    }
    center = p0 + offset + std::sqrt(h2 / w2) * w;
    return true;
}

}  // namespace o3d::geometry::ball_pivoting
