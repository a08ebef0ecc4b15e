// SPDX-License-Identifier: MIT
#include "o3d/visualization/view_control.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3d checked_direction(const Eigen::Vector3d& v, const char* name) {
    if (!v.allFinite() || v.norm() < 1e-12) throw InvalidArgument(std::string(name) + " must be finite and non-zero");
    return v.normalized();
}

double distance_for(const ViewStatus& s) {
    return s.zoom * s.box.max_extent() / std::tan(s.field_of_view * 0.5 / 180.0 * kPi);
}

}  // namespace

void ViewControl::reset() {
    status_.field_of_view = kDefaultFieldOfView;
    status_.zoom = kDefaultZoom;
    status_.lookat = status_.box.center();
    status_.up = Eigen::Vector3d::UnitY();
    status_.front = Eigen::Vector3d::UnitZ();
}

void ViewControl::rotate(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) throw InvalidArgument("rotate needs finite pixel steps");
    const double alpha = x * kRotationRadianPerPixel, beta = y * kRotationRadianPerPixel;
    ViewStatus& s = status_;
    Eigen::Vector3d right = s.up.cross(s.front).normalized();
    s.front = (s.front * std::cos(alpha) - right * std::sin(alpha)).normalized();
    right = s.up.cross(s.front).normalized();
    s.front = (s.front * std::cos(beta) + s.up * std::sin(beta)).normalized();
    s.up = s.front.cross(right).normalized();
}

void ViewControl::translate(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) throw InvalidArgument("translate needs finite pixel steps");
    ViewStatus& s = status_;
    const Eigen::Vector3d right = s.up.cross(s.front).normalized();
    const Eigen::Vector3d up = s.front.cross(right).normalized();
    const double view_ratio = s.zoom * s.box.max_extent();
    s.lookat += (right * -x + up * y) / height_ * view_ratio * 2.0;
}

void ViewControl::scale(double scale) {
    if (!std::isfinite(scale)) throw InvalidArgument("scale must be finite");
    status_.zoom = std::clamp(status_.zoom + scale * kZoomStep, kMinZoom, kMaxZoom);
}

void ViewControl::change_field_of_view(double step) {
    if (!std::isfinite(step)) throw InvalidArgument("change_field_of_view needs a finite step");
    status_.field_of_view = std::clamp(status_.field_of_view + step * kFieldOfViewStep, kMinFieldOfView, kMaxFieldOfView);
}

void ViewControl::set_front(const Eigen::Vector3d& front) { status_.front = checked_direction(front, "front"); }
void ViewControl::set_up(const Eigen::Vector3d& up) { status_.up = checked_direction(up, "up"); }

void ViewControl::set_lookat(const Eigen::Vector3d& lookat) {
    if (!lookat.allFinite()) throw InvalidArgument("lookat must be finite");
    status_.lookat = lookat;
}

void ViewControl::set_zoom(double zoom) {
    if (!std::isfinite(zoom)) throw InvalidArgument("zoom must be finite");
    status_.zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
}

void ViewControl::set_status(const ViewStatus& status) {
    // view_from_lookat checks the vectors, the zoom and the field of view.
    view_from_lookat(status.lookat, status.front, status.up, status.zoom, status.box, width_, height_,
                     status.field_of_view);
    status_ = status;
    status_.front.normalize();
    status_.up.normalize();
}

camera::PinholeCameraParameters ViewControl::to_pinhole() const {
    const ViewStatus& s = status_;
    return view_from_lookat(s.lookat, s.front, s.up, s.zoom, s.box, width_, height_, s.field_of_view);
}

void ViewControl::from_pinhole(const camera::PinholeCameraParameters& p) {
    const camera::PinholeCameraIntrinsic& k = p.intrinsic;
    if (k.width != width_ || k.height != height_)
        throw InvalidArgument("the camera is " + std::to_string(k.width) + " x " + std::to_string(k.height) +
                              ", the window " + std::to_string(width_) + " x " + std::to_string(height_));
    const double tolerance = 1e-6 * std::max(1.0, std::abs(k.fy));
    if (!(std::abs(k.cx - (width_ / 2.0 - 0.5)) < 1e-6 && std::abs(k.cy - (height_ / 2.0 - 0.5)) < 1e-6))
        throw InvalidArgument("the view control needs the principal point at the window's centre (" +
                              std::to_string(width_ / 2.0 - 0.5) + ", " + std::to_string(height_ / 2.0 - 0.5) + ")");
    if (!(k.fy > 0) || !(std::abs(k.fx - k.fy) < tolerance))
        throw InvalidArgument("the view control needs fx = fy > 0");
    const double fov = 2.0 * std::atan(height_ / (2.0 * k.fy)) * 180.0 / kPi;
    if (!(fov >= kMinFieldOfView - 1e-9 && fov <= kMaxFieldOfView + 1e-9))
        throw InvalidArgument("the camera's field of view " + std::to_string(fov) + " is outside [5, 90] degrees");
    check_rigid(p.extrinsic);
    const Eigen::Matrix3d r = p.extrinsic.block<3, 3>(0, 0);
    ViewStatus s = status_;
    s.field_of_view = std::clamp(fov, kMinFieldOfView, kMaxFieldOfView);
    s.up = -r.row(1).transpose();
    s.front = -r.row(2).transpose();
    const Eigen::Vector3d eye = -r.transpose() * p.extrinsic.block<3, 1>(0, 3);
    s.lookat = eye - s.front * distance_for(s);
    status_ = s;
}

int ViewTrajectory::num_frames() const {
    if (views.empty()) return 0;
    const int n = int(views.size());
    return is_loop ? (interval + 1) * n : (interval + 1) * (n - 1) + 1;
}

ViewStatus ViewTrajectory::frame(int k) const {
    if (k < 0 || k >= num_frames())
        throw InvalidArgument("frame " + std::to_string(k) + " of a trajectory of " + std::to_string(num_frames()));
    const int i = k / (interval + 1);
    const double t = double(k % (interval + 1)) / double(interval + 1);
    const ViewStatus& a = views[size_t(i) % views.size()];
    if (t == 0) return a;
    const ViewStatus& b = views[size_t(i + 1) % views.size()];
    auto mix = [t](const auto& x, const auto& y) { return (1 - t) * x + t * y; };
    ViewStatus s;
    s.box.min_bound = mix(a.box.min_bound, b.box.min_bound);
    s.box.max_bound = mix(a.box.max_bound, b.box.max_bound);
    s.field_of_view = mix(a.field_of_view, b.field_of_view);
    s.zoom = mix(a.zoom, b.zoom);
    s.lookat = mix(a.lookat, b.lookat);
    s.front = mix(a.front, b.front).normalized();
    s.up = mix(a.up, b.up).normalized();
    return s;
}

}  // namespace o3d::visualization
