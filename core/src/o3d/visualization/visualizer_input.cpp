// SPDX-License-Identifier: MIT
// The Visualizer's own key bindings (Open3D's) and the GLFW callbacks that feed it input.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

#include "o3d/io/image_io.h"
#include "o3d/io/file_bytes.h"
#include "o3d/visualization/glfw_window.h"
#include "o3d/visualization/visualizer.h"

namespace o3d::visualization {
namespace {

/// @brief "2026-12-03-11-37-48": Open3D's capture file names carry the local time like this.
std::string timestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d-%H-%M-%S", &local);
    return text;
}

}  // namespace

std::string Visualizer::help_text() {
    return "o3d visualizer: mouse and keys\n"
           "  Left drag            rotate the view\n"
           "  Ctrl + left drag     translate the view (also the middle button)\n"
           "  Wheel                zoom in or out\n"
           "  Shift + left click   pick a point (VisualizerWithEditing); Shift + right click drops the last\n"
           "  K                    lock the view to select a region (VisualizerWithEditing): left drag for a\n"
           "                       rectangle, Ctrl + left clicks for a polygon; C crops to it; K again leaves\n"
           "  H                    print this help\n"
           "  R                    reset the view\n"
           "  [ / ]                narrow / widen the field of view\n"
           "  + / -                bigger / smaller points\n"
           "  N                    show point normals on / off\n"
           "  W                    mesh wireframe on / off\n"
           "  B                    mesh back faces on / off\n"
           "  L                    lighting on / off\n"
           "  S                    flat / smooth mesh shading\n"
           "  0-4, 9               point colour: default, colour, x, y, z, normal (with Shift: mesh colour)\n"
           "  P                    save the screen to ScreenCapture_<time>.png and the camera to ScreenCamera_<time>.json\n"
           "  Ctrl + C             copy the view (ViewTrajectory JSON) to the clipboard\n"
           "  Q or Esc             close the window\n";
}

void Visualizer::default_key_action(int key, int mods) {
    if (!renderer_) return;
    RenderOption o = renderer_->render_option();
    const bool ctrl = mods & keys::kModControl, shift = mods & keys::kModShift;
    switch (key) {
        case GLFW_KEY_ESCAPE:
        case GLFW_KEY_Q: close(); return;
        case GLFW_KEY_H: std::fputs(help_text().c_str(), stdout); return;
        case GLFW_KEY_R: reset_view_point(); return;
        case GLFW_KEY_LEFT_BRACKET: view_->change_field_of_view(-1.0); break;
        case GLFW_KEY_RIGHT_BRACKET: view_->change_field_of_view(1.0); break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD: o.point_size = std::min(o.point_size + 1.0, 25.0); break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: o.point_size = std::max(o.point_size - 1.0, 1.0); break;
        case GLFW_KEY_N: o.point_show_normal = !o.point_show_normal; break;
        case GLFW_KEY_W: o.mesh_show_wireframe = !o.mesh_show_wireframe; break;
        case GLFW_KEY_B: o.mesh_show_back_face = !o.mesh_show_back_face; break;
        case GLFW_KEY_L: o.light_on = !o.light_on; break;
        case GLFW_KEY_S: o.mesh_shade = o.mesh_shade == MeshShade::Flat ? MeshShade::Smooth : MeshShade::Flat; break;
        case GLFW_KEY_0: case GLFW_KEY_1: case GLFW_KEY_2: case GLFW_KEY_3: case GLFW_KEY_4: case GLFW_KEY_9: {
            const ColorOption c = ColorOption(key - GLFW_KEY_0);
            (shift ? o.mesh_color : o.point_color) = c;
            break;
        }
        case GLFW_KEY_P: {
            const std::string stamp = timestamp();
            io::write_image("ScreenCapture_" + stamp + ".png", capture_screen());
            const std::string json = view_status_json();
            io::detail::write_file("ScreenCamera_" + stamp + ".json", std::vector<uint8_t>(json.begin(), json.end()));
            return;
        }
        case GLFW_KEY_C:
            if (ctrl && window_) glfw().set_clipboard_string(window_->handle(), view_status_json().c_str());
            else if (!ctrl && selecting_ && selection_.size() >= 3) crop_to_selection();
            return;
        case GLFW_KEY_K:
            if (editing_) toggle_selecting();
            return;
        default: return;
    }
    renderer_->set_render_option(o);
    redraw_ = true;
}

template <typename F>
void Visualizer::from_window(F&& f) {
    // An exception must not unwind through GLFW's C code: keep it for poll_events to rethrow.
    if (pending_) return;
    try {
        f();
    } catch (...) {
        pending_ = std::current_exception();
    }
}

void Visualizer::install_input(GlfwWindow& window) {
    const GlfwApi& api = glfw();
    GLFWwindow* w = window.handle();
    api.set_key_callback(w, [](GLFWwindow* w, int key, int, int action, int mods) {
        auto* v = static_cast<Visualizer*>(glfw().get_window_user_pointer(w));
        v->from_window([&] { v->key_event(key, action, mods); });
    });
    api.set_mouse_button_callback(w, [](GLFWwindow* w, int button, int action, int mods) {
        auto* v = static_cast<Visualizer*>(glfw().get_window_user_pointer(w));
        v->from_window([&] { v->mouse_button(button, action, mods); });
    });
    api.set_cursor_pos_callback(w, [](GLFWwindow* w, double x, double y) {
        auto* v = static_cast<Visualizer*>(glfw().get_window_user_pointer(w));
        v->from_window([&] { v->mouse_move(x, y); });
    });
    api.set_scroll_callback(w, [](GLFWwindow* w, double dx, double dy) {
        auto* v = static_cast<Visualizer*>(glfw().get_window_user_pointer(w));
        v->from_window([&] { v->scroll(dx, dy); });
    });
    api.set_window_refresh_callback(w, [](GLFWwindow* w) {
        static_cast<Visualizer*>(glfw().get_window_user_pointer(w))->redraw_ = true;
    });
}

}  // namespace o3d::visualization
