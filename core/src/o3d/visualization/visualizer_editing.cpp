// SPDX-License-Identifier: MIT
// VisualizerWithEditing's cropping: selecting a region of the window and keeping what projects into it.
#include <Eigen/Geometry>

#include "o3d/geometry/mesh_crop.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"
#include "o3d/visualization/selection_polygon_volume.h"
#include "o3d/visualization/visualizer.h"

namespace o3d::visualization {

void Visualizer::toggle_selecting() {
    selecting_ = !selecting_;
    dragging_rectangle_ = false;
    selection_.clear();
    show_selection();
}

bool Visualizer::select_with_mouse_button(int button, int action, int mods) {
    if (!selecting_ || button != keys::kMouseLeft) return selecting_;  // other buttons do nothing while selecting
    if (action == keys::kRelease) {
        dragging_rectangle_ = false;
        return true;
    }
    const Eigen::Vector2d at(mouse_x_, mouse_y_);
    if (mods & keys::kModControl) {  // a polygon corner (a rectangle being drawn is dropped)
        if (selection_is_rectangle_) selection_.clear();
        selection_is_rectangle_ = dragging_rectangle_ = false;
        selection_.push_back(at);
    } else {
        selection_is_rectangle_ = dragging_rectangle_ = true;
        rectangle_start_ = at;
        selection_.assign(4, at);
    }
    show_selection();
    return true;
}

bool Visualizer::select_with_mouse_move() {
    if (!selecting_) return false;
    if (dragging_rectangle_) {
        const Eigen::Vector2d a = rectangle_start_;
        selection_ = {a, {mouse_x_, a.y()}, {mouse_x_, mouse_y_}, {a.x(), mouse_y_}};
        show_selection();
    }
    return true;  // the view stays locked
}

void Visualizer::show_selection() {
    if (!renderer_) return;
    const RenderOption o = renderer_->render_option();
    // A colour that shows on the background: black on light ones, white on dark.
    const Eigen::Vector3d color = o.background_color.mean() > 0.5 ? Eigen::Vector3d::Zero() : Eigen::Vector3d::Ones();
    renderer_->set_outline(selecting_ ? selection_ : std::vector<Eigen::Vector2d>{}, color);
    redraw_ = true;
}

void Visualizer::crop_to_selection() {
    require_window("crop_to_selection");
    if (!editing_cloud_ && !editing_mesh_)
        throw InvalidArgument("nothing to crop: the first geometry of a VisualizerWithEditing must be a point cloud or a mesh");
    if (selection_.size() < 3) throw InvalidArgument("crop needs a selection of at least 3 corners (press K, then drag)");
    // Keep the points whose projection lies inside the selection, in front of the camera.
    const camera::PinholeCameraParameters camera = view_->to_pinhole();
    const camera::PinholeCameraIntrinsic& k = camera.intrinsic;
    std::vector<uint8_t> inside(editing_points_.size(), 0);
    for (size_t i = 0; i < editing_points_.size(); ++i) {
        const Eigen::Vector4d p = camera.extrinsic * editing_points_[i].homogeneous();
        if (!(p.z() > 0)) continue;
        inside[i] = inside_polygon(selection_, k.fx * p.x() / p.z() + k.cx, k.fy * p.y() / p.z() + k.cy);
    }
    ++crops_;
    const std::string path = crop_directory_.empty() ? "" : crop_directory_ + "/cropped_" + std::to_string(crops_) + ".ply";
    if (editing_cloud_) {
        cropped_cloud_ = geometry::select_by_mask(*editing_cloud_, inside);
        cropped_mesh_.reset();
        add_geometry(editing_name_, *cropped_cloud_, false);
        if (!path.empty()) io::write_point_cloud(path, *cropped_cloud_);
    } else {
        cropped_mesh_ = geometry::keep_triangles_inside(*editing_mesh_, inside);
        cropped_cloud_.reset();
        add_geometry(editing_name_, *cropped_mesh_, false);
        if (!path.empty()) io::write_triangle_mesh(path, *cropped_mesh_);
    }
    picked_.clear();  // indices into the old vertices
    selecting_ = false;
    selection_.clear();
    show_selection();
}

}  // namespace o3d::visualization
