// SPDX-License-Identifier: MIT
#pragma once
/// @file camera.hpp
/// @brief o3dpp::PinholeIntrinsic (the C value struct with presets) and o3dpp::CameraTrajectory.
#include <cstdint>
#include <vector>

#include "o3d/camera.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief o3d.camera.PinholeCameraIntrinsic: the frozen C struct, so it passes straight through.
struct PinholeIntrinsic : o3d_pinhole_intrinsic_t {
    using Preset = IntrinsicPreset;
    PinholeIntrinsic() : o3d_pinhole_intrinsic_t{0, 0, 0.0, 0.0, 0.0, 0.0} {}
    PinholeIntrinsic(int32_t w, int32_t h, double fx_, double fy_, double cx_, double cy_)
        : o3d_pinhole_intrinsic_t{w, h, fx_, fy_, cx_, cy_} {}
    explicit PinholeIntrinsic(const o3d_pinhole_intrinsic_t& c) : o3d_pinhole_intrinsic_t(c) {}
    explicit PinholeIntrinsic(Preset preset) : PinholeIntrinsic() {
        check(o3d_pinhole_intrinsic_set_preset(this, static_cast<int32_t>(preset)));
    }
    /// @brief Row-major 3x3 camera matrix.
    Mat3 intrinsic_matrix() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }
    bool operator==(const PinholeIntrinsic& o) const {
        return width == o.width && height == o.height && fx == o.fx && fy == o.fy && cx == o.cx && cy == o.cy;
    }
    bool operator!=(const PinholeIntrinsic& o) const { return !(*this == o); }
};

/// @brief One pose: intrinsic and row-major world-to-camera extrinsic.
struct PinholeCameraParameters {
    PinholeIntrinsic intrinsic;
    Mat4 extrinsic = identity4();
};

/// @brief o3d.camera.PinholeCameraTrajectory. Move-only.
class CameraTrajectory : public Owner<CameraTrajectory, o3d_camera_trajectory_t, &o3d_camera_trajectory_destroy> {
public:
    CameraTrajectory() : Owner(make(&o3d_camera_trajectory_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit CameraTrajectory(o3d_camera_trajectory_t* owned) : Owner(owned) {}

    std::size_t size() const { return query(&o3d_camera_trajectory_size); }
    bool empty() const { return size() == 0; }
    /// @brief Pose `index` (out of range → Error).
    PinholeCameraParameters at(std::size_t index) const {
        PinholeCameraParameters p;
        check(o3d_camera_trajectory_get(&p.intrinsic, p.extrinsic.data(), get(), index));
        return p;
    }
    std::vector<PinholeCameraParameters> parameters() const {
        return detail::collect(size(), [&](std::size_t i) { return at(i); });
    }
    /// @brief Append a pose (extrinsic's last row must be 0 0 0 1).
    void push_back(const PinholeIntrinsic& intrinsic, const Mat4& extrinsic) {
        check(o3d_camera_trajectory_append(get(), &intrinsic, extrinsic.data()));
    }
    void push_back(const PinholeCameraParameters& p) { push_back(p.intrinsic, p.extrinsic); }
    void clear() { check(o3d_camera_trajectory_clear(get())); }
};

}  // namespace o3dpp
