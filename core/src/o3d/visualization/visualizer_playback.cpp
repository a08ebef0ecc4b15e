// SPDX-License-Identifier: MIT
// draw_geometries_with_custom_animation's playback: a ViewTrajectory shown frame by frame, with captures.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "o3d/io/image_io.h"
#include "o3d/utility/error.h"
#include "o3d/visualization/visualizer.h"

namespace o3d::visualization {

geometry::Image Visualizer::depth_to_uint16(const geometry::Image& depth, double scale) {
    if (!(scale > 0) || !std::isfinite(scale)) throw InvalidArgument("depth_scale must be finite and > 0");
    geometry::Image out;
    out.width = depth.width;
    out.height = depth.height;
    out.num_channels = 1;
    out.bytes_per_channel = 2;
    out.data.resize(out.byte_size());
    for (int v = 0; v < depth.height; ++v)
        for (int u = 0; u < depth.width; ++u) {
            const double d = *depth.pixel<float>(u, v) * scale;
            *out.pixel<uint16_t>(u, v) = uint16_t(std::clamp(std::lround(d), 0L, 65535L));
        }
    return out;
}

void Visualizer::play_view_trajectory(const ViewTrajectory& trajectory, const std::string& capture_dir,
                                      bool with_depth, const std::function<bool(double)>& progress) {
    require_window("play_view_trajectory");
    const int n = trajectory.num_frames();
    for (int k = 0; k < n; ++k) {
        view_->set_status(trajectory.frame(k));
        redraw_ = true;
        poll_events();
        if (!capture_dir.empty()) {
            char name[32];
            std::snprintf(name, sizeof name, "/image_%06d.png", k);
            io::write_image(capture_dir + name, capture_screen());
            if (with_depth) {
                std::snprintf(name, sizeof name, "/depth_%06d.png", k);
                io::write_image(capture_dir + name, depth_to_uint16(capture_depth(), 1000.0));
            }
        }
        if (progress && !progress(double(k + 1) / n)) throw Cancelled("view trajectory playback cancelled");
    }
}

}  // namespace o3d::visualization
