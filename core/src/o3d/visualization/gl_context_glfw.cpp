// SPDX-License-Identifier: MIT
// GLFW windows: the renderer's fallback context when EGL gives nothing (hidden), and the Visualizer's window.
#include <dlfcn.h>
#include <epoxy/gl.h>

#include "o3d/visualization/glfw_window.h"

namespace o3d::visualization {

std::unique_ptr<GlfwWindow> GlfwWindow::create(const std::string& title, int width, int height, int left, int top,
                                               bool visible, std::string* why) {
    const GlfwApi& api = glfw();
    if (!api.missing.empty()) {
        *why = api.missing;
        return nullptr;
    }
    // libepoxy resolves GLX-context entry points through libGL and aborts without it.
    static void* const libgl = dlopen("libGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (!libgl) {
        *why = "libGL.so.1 not found";
        return nullptr;
    }
    std::lock_guard<std::mutex> lock(glfw_mutex());
    if (!glfw_acquire(why)) return nullptr;
    api.default_window_hints();
    api.window_hint(GLFW_VISIBLE, GLFW_FALSE);  // shown after it is placed
    api.window_hint(GLFW_RESIZABLE, GLFW_FALSE);  // the framebuffer behind it has a fixed size
    api.window_hint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    api.window_hint(GLFW_CONTEXT_VERSION_MINOR, 3);
    api.window_hint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    api.window_hint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);  // wide lines stay allowed
    GLFWwindow* window = api.create_window(width, height, title.c_str(), nullptr, nullptr);
    if (!window) {
        *why = "glfwCreateWindow (OpenGL 3.3 core): " + glfw_last_error();
        glfw_release();
        return nullptr;
    }
    if (left >= 0 && top >= 0) api.set_window_pos(window, left, top);
    if (visible) api.show_window(window);
    return std::unique_ptr<GlfwWindow>(new GlfwWindow(window));
}

GlfwWindow::~GlfwWindow() {
    std::lock_guard<std::mutex> lock(glfw_mutex());
    glfw().destroy_window(window_);
    glfw_release();
}

void GlfwWindow::make_current() { glfw().make_context_current(window_); }
void GlfwWindow::release() { glfw().make_context_current(nullptr); }

std::unique_ptr<GLContext> create_glfw_context(std::string* why) {
    return GlfwWindow::create("o3d", 16, 16, -1, -1, false, why);
}

}  // namespace o3d::visualization
