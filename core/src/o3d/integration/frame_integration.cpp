// SPDX-License-Identifier: MIT
#include "o3d/integration/frame_integration.h"

#include <algorithm>
#include <cmath>

namespace o3d::integration::detail {

void integrate_block(VoxelBlock& block, const BlockMap& map, const FrameView& frame, int x_begin, int x_end) {
    const int side = map.side();
    const double voxel_length = map.voxel_length();
    const Eigen::Vector3d block_origin = map.origin() + voxel_length * double(side) * block.key.cast<double>();
    const float safe_width = float(frame.width) - 0.0001f, safe_height = float(frame.height) - 0.0001f;
    const float inv_trunc = 1.0f / frame.sdf_trunc;
    // Walking z moves the camera-space point by a constant step, so each voxel costs one add, not a product.
    const Eigen::Vector3f step = frame.rotation.col(2) * float(voxel_length);
    for (int x = x_begin; x < x_end; ++x) {
        for (int y = 0; y < side; ++y) {
            const Eigen::Vector3d first = block_origin + voxel_length * Eigen::Vector3d(x + 0.5, y + 0.5, 0.5);
            Eigen::Vector3f p = frame.rotation * first.cast<float>() + frame.translation;
            const size_t row = (size_t(x) * size_t(side) + size_t(y)) * size_t(side);
            for (int z = 0; z < side; ++z, p += step) {
                if (p.z() <= 0.0f) continue;
                const float u_f = p.x() * frame.fx / p.z() + frame.cx + 0.5f;
                const float v_f = p.y() * frame.fy / p.z() + frame.cy + 0.5f;
                if (!(u_f >= 0.0001f && u_f < safe_width && v_f >= 0.0001f && v_f < safe_height)) continue;
                const size_t pixel = size_t(int(v_f)) * size_t(frame.width) + size_t(int(u_f));
                const float depth = frame.depth[pixel];
                if (!(depth > 0.0f) || !std::isfinite(depth)) continue;
                const float sdf = (depth - p.z()) * frame.distance_multiplier[pixel];
                if (sdf <= -frame.sdf_trunc) continue;
                const size_t i = row + size_t(z);
                const float w = block.weight[i];
                const float inv_w = 1.0f / (w + 1.0f);
                block.tsdf[i] = (block.tsdf[i] * w + std::min(1.0f, sdf * inv_trunc)) * inv_w;
                if (frame.rgb) {
                    const uint8_t* c = frame.rgb + 3 * pixel;
                    const Eigen::Vector3f rgb(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f);
                    block.color[i] = (block.color[i] * w + rgb) * inv_w;
                } else if (frame.intensity) {
                    const float g = frame.intensity[pixel];
                    block.color[i] = (block.color[i] * w + Eigen::Vector3f(g, g, g)) * inv_w;
                }
                block.weight[i] = w + 1.0f;
            }
        }
    }
}

}  // namespace o3d::integration::detail
