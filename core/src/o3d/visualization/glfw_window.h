// SPDX-License-Identifier: MIT
#pragma once
/// @file glfw_window.h
/// @brief A GLFW window with an OpenGL 3.3 core context: hidden (the renderer's fallback context) or shown
/// (the Visualizer's window). Needs an X display, e.g. Xvfb.
#include <memory>
#include <string>

#include "o3d/visualization/gl_context.h"
#include "o3d/visualization/glfw_api.h"

namespace o3d::visualization {

class GlfwWindow final : public GLContext {
public:
    /// @brief nullptr with `why` filled when GLFW, libGL or a display is missing. left/top < 0: GLFW's place.
    static std::unique_ptr<GlfwWindow> create(const std::string& title, int width, int height, int left, int top,
                                              bool visible, std::string* why);
    ~GlfwWindow() override;
    void make_current() override;
    void release() override;
    Backend backend() const override { return Backend::Glfw; }
    GLFWwindow* handle() const { return window_; }

private:
    explicit GlfwWindow(GLFWwindow* window) : window_(window) {}
    GLFWwindow* window_;
};

}  // namespace o3d::visualization
