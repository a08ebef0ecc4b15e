// SPDX-License-Identifier: MIT
#pragma once
/// @file view_control.h
/// @brief Open3D's legacy ViewControl: a camera looking at `lookat` from `front`, `zoom` times the scene's
/// extent away (in units of the field of view), moved by mouse-sized steps and convertible to and from
/// pinhole parameters.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/visualization/view_camera.h"

namespace o3d::visualization {

/// @brief Everything that fixes a view: one entry of Open3D's ViewTrajectory JSON ("view status").
struct ViewStatus {
    SceneBox box;
    double field_of_view = kDefaultFieldOfView;
    double zoom = kDefaultZoom;
    Eigen::Vector3d lookat = Eigen::Vector3d::Zero();
    Eigen::Vector3d front = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
};

class ViewControl {
public:
    /// @brief Open3D's steps: radians of rotation per pixel, zoom per scale unit, degrees of field of view.
    static constexpr double kRotationRadianPerPixel = 0.003;
    static constexpr double kZoomStep = 0.02;
    static constexpr double kFieldOfViewStep = 5.0;

    ViewControl(int width, int height) : width_(width), height_(height) {}

    int width() const { return width_; }
    int height() const { return height_; }

    /// @brief The box the view frames (zoom is relative to its largest extent).
    const SceneBox& bounding_box() const { return status_.box; }
    void set_bounding_box(const SceneBox& box) { status_.box = box; }

    /// @brief Open3D's Reset: look at the box's centre from +z with +y up, zoom 0.7, field of view 60.
    void reset();
    /// @brief Drag by (x, y) pixels: turn `front` about `up` by x, then about the new right axis by y.
    void rotate(double x, double y);
    /// @brief Drag by (x, y) pixels: move lookat in the image plane, a window height being 2 * zoom * extent.
    void translate(double x, double y);
    /// @brief zoom += scale * 0.02, kept in [0.02, 2].
    void scale(double scale);
    /// @brief field of view += step * 5 degrees, kept in [5, 90].
    void change_field_of_view(double step);

    // Setters throw InvalidArgument on non-finite or zero vectors; zoom is kept in [0.02, 2] as Open3D does.
    void set_front(const Eigen::Vector3d& front);
    void set_lookat(const Eigen::Vector3d& lookat);
    void set_up(const Eigen::Vector3d& up);
    void set_zoom(double zoom);

    const ViewStatus& status() const { return status_; }
    /// @brief Checked (finite vectors, up not parallel to front, zoom and field of view in range).
    void set_status(const ViewStatus& status);

    /// @brief The camera a render uses (the window's size; principal point at its centre).
    camera::PinholeCameraParameters to_pinhole() const;
    /// @brief Take a camera: its size must be the window's, its principal point the centre, fx = fy, the
    /// field of view in [5, 90] degrees and the extrinsic rigid; the zoom is kept (lookat moves along the
    /// optical axis to match it). Throws InvalidArgument otherwise, leaving the view unchanged.
    void from_pinhole(const camera::PinholeCameraParameters& parameters);

private:
    int width_, height_;
    ViewStatus status_;
};

/// @brief Open3D's ViewTrajectory: key views and `interval` frames interpolated between two of them.
struct ViewTrajectory {
    std::vector<ViewStatus> views;
    int interval = 29;
    bool is_loop = false;

    int num_frames() const;
    /// @brief Frame k of num_frames(): views interpolated linearly (directions renormalised).
    ViewStatus frame(int k) const;
};

/// @brief ViewTrajectory JSON (Open3D's layout, "class_name": "ViewTrajectory"). Throws ParseError.
ViewTrajectory view_trajectory_from_json(const std::string& text);
std::string view_trajectory_to_json(const ViewTrajectory& trajectory);

}  // namespace o3d::visualization
