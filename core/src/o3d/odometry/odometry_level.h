// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_level.h
/// @brief One pyramid level packed the way the Gauss-Newton pass reads it: per source pixel its back-projected
/// point and intensity, per target pixel everything a correspondence looks up, each in one record. The pass then
/// touches one record per source pixel and one per landing pixel instead of six separate images.
#include <vector>

#include "o3d/odometry/odometry_frames.h"

namespace o3d::odometry::detail {

/// @brief z is the (masked) depth: NaN where the pixel has none. x, y, z are back-projected in float, as
/// Open3D's point image is.
struct SourcePixel {
    float x, y, z, intensity;
};

/// @brief The target's intensity and depth with their unscaled Sobel gradients; a depth gradient that is NaN
/// (next to a pixel without depth) is stored as 0, which is what the geometric row uses for it.
struct TargetPixel {
    float intensity, depth, dx, dy, ddx, ddy;
};

struct PackedLevel {
    LevelCamera camera;
    std::vector<SourcePixel> source;
    std::vector<TargetPixel> target;
    const SourcePixel& source_at(int u, int v) const { return source[size_t(v) * size_t(camera.width) + size_t(u)]; }
    const TargetPixel& target_at(int u, int v) const { return target[size_t(v) * size_t(camera.width) + size_t(u)]; }
};

/// @brief A source pixel (u_s of the row being visited) and the target pixel it corresponds to.
struct Match {
    int u_s, u_t, v_t;
};

/// @brief For each source row v_s of [v_first, v_last), call f(row, matches, n): the n pixels of `row` that
/// `warp` moves onto a target pixel whose depth is within depth_diff_max of the moved point's, in scan order, as
/// detail::visit_correspondences finds them. `matches` holds room for a row.
template <typename F>
void visit_matches(const PackedLevel& level, const Warp& warp, double depth_diff_max, int v_first, int v_last,
                   std::vector<Match>& matches, F&& f) {
    const int w = level.camera.width, h = level.camera.height;
    // A row is matched first, then f runs over its matches: two short loops whose iterations the CPU overlaps,
    // instead of one whose every pixel waits on its warp's divisions and target lookup before its rows start.
    matches.resize(static_cast<size_t>(w));
    for (int v_s = v_first; v_s < v_last; ++v_s) {
        const SourcePixel* row = &level.source_at(0, v_s);
        size_t n = 0;
        for (int u_s = 0; u_s < w; ++u_s) {
            const float d_s = row[u_s].z;
            if (std::isnan(d_s)) continue;
            int u_t, v_t;
            double z;
            if (!warp.apply(u_s, v_s, d_s, w, h, u_t, v_t, z)) continue;
            matches[n] = {u_s, u_t, v_t};
            n += Warp::depths_agree(z, level.target_at(u_t, v_t).depth, depth_diff_max);
        }
        f(row, matches.data(), n);
    }
}

/// @brief `camera` is the level's; source and target are its images, all camera.width x camera.height.
PackedLevel pack_level(const LevelCamera& camera, const FrameLevel& source, const FrameLevel& target);

}  // namespace o3d::odometry::detail
