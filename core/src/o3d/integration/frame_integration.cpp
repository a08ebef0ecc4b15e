// SPDX-License-Identifier: MIT
// The voxel update is the hot loop of integration (millions of voxels a frame), so it is written on plain floats:
// one division a voxel for the projection and one for the running average, colour scaled by a product.
#include "o3d/integration/frame_integration.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace o3d::integration::detail {

void integrate_block(VoxelBlock& block, const BlockMap& map, const FrameView& frame, int x_begin, int x_end) {
    const int side = map.side();
    const double voxel_length = map.voxel_length();
    const Eigen::Vector3d block_origin = map.origin() + voxel_length * double(side) * block.key.cast<double>();
    const float safe_width = float(frame.width) - 0.0001f, safe_height = float(frame.height) - 0.0001f;
    const float inv_trunc = 1.0f / frame.sdf_trunc, trunc = frame.sdf_trunc;
    const float fx = frame.fx, fy = frame.fy, cx = frame.cx + 0.5f, cy = frame.cy + 0.5f;
    const size_t width = size_t(frame.width);
    // Walking z moves the camera-space point by a constant step, so each voxel costs adds, not a product.
    const Eigen::Vector3f step = frame.rotation.col(2) * float(voxel_length);
    float* tsdf = block.tsdf.data();
    float* weight = block.weight.data();
    Eigen::Vector3f* color = block.color.empty() ? nullptr : block.color.data();
    constexpr float kByte = 1.0f / 255.0f;
    for (int x = x_begin; x < x_end; ++x) {
        for (int y = 0; y < side; ++y) {
            const Eigen::Vector3d first = block_origin + voxel_length * Eigen::Vector3d(x + 0.5, y + 0.5, 0.5);
            const Eigen::Vector3f p0 = frame.rotation * first.cast<float>() + frame.translation;
            float px = p0.x(), py = p0.y(), pz = p0.z();
            const size_t row = (size_t(x) * size_t(side) + size_t(y)) * size_t(side);
            for (int z = 0; z < side; ++z, px += step.x(), py += step.y(), pz += step.z()) {
                if (pz <= 0.0f) continue;
                const float inv_z = 1.0f / pz;
                const float u_f = px * fx * inv_z + cx, v_f = py * fy * inv_z + cy;
                if (!(u_f >= 0.0001f && u_f < safe_width && v_f >= 0.0001f && v_f < safe_height)) continue;
                const int u = int(u_f), v = int(v_f);
                const size_t pixel = size_t(v) * width + size_t(u);
                const float depth = frame.depth[pixel];
                if (!(depth > 0.0f && depth <= FLT_MAX)) continue;  // holes, NaN and infinity
                const float sdf = (depth - pz) * std::sqrt(1.0f + frame.ray_x2[u] + frame.ray_y2[v]);
                if (sdf <= -trunc) continue;
                const size_t i = row + size_t(z);
                const float w = weight[i];
                const float inv_w = 1.0f / (w + 1.0f);
                tsdf[i] = (tsdf[i] * w + std::min(1.0f, sdf * inv_trunc)) * inv_w;
                if (frame.rgb) {
                    const uint8_t* c = frame.rgb + 3 * pixel;
                    float* out = color[i].data();
                    out[0] = (out[0] * w + float(c[0]) * kByte) * inv_w;
                    out[1] = (out[1] * w + float(c[1]) * kByte) * inv_w;
                    out[2] = (out[2] * w + float(c[2]) * kByte) * inv_w;
                } else if (frame.intensity) {
                    const float g = frame.intensity[pixel];
                    float* out = color[i].data();
                    for (int k = 0; k < 3; ++k) out[k] = (out[k] * w + g) * inv_w;
                }
                weight[i] = w + 1.0f;
            }
        }
    }
}

}  // namespace o3d::integration::detail
