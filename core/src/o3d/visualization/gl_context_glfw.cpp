// SPDX-License-Identifier: MIT
// The fallback when EGL gives nothing: a hidden GLFW window (an X display is needed, e.g. Xvfb).
#include <dlfcn.h>
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <mutex>
#include <string>

#include "o3d/visualization/gl_context.h"

namespace o3d::visualization {
namespace {

std::mutex glfw_mutex;  // guards the count of live windows: GLFW is initialised while any exists
int glfw_users = 0;
thread_local std::string glfw_last_error;

void remember_error(int, const char* description) { glfw_last_error = description ? description : "?"; }

class GlfwContext final : public GLContext {
public:
    explicit GlfwContext(GLFWwindow* window) : window_(window) {}
    ~GlfwContext() override {
        std::lock_guard<std::mutex> lock(glfw_mutex);
        glfwDestroyWindow(window_);
        if (--glfw_users == 0) glfwTerminate();
    }
    void make_current() override { glfwMakeContextCurrent(window_); }
    void release() override { glfwMakeContextCurrent(nullptr); }
    Backend backend() const override { return Backend::Glfw; }

private:
    GLFWwindow* window_;
};

}  // namespace

std::unique_ptr<GLContext> create_glfw_context(std::string* why) {
    // libepoxy resolves GLX-context entry points through libGL and aborts without it.
    static void* const libgl = dlopen("libGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (!libgl) {
        *why = "libGL.so.1 not found";
        return nullptr;
    }
    std::lock_guard<std::mutex> lock(glfw_mutex);
    glfwSetErrorCallback(remember_error);
    if (glfw_users == 0 && !glfwInit()) {
        *why = "glfwInit: " + glfw_last_error;
        return nullptr;
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);  // wide lines stay allowed
    GLFWwindow* window = glfwCreateWindow(16, 16, "o3d", nullptr, nullptr);
    if (!window) {
        *why = "glfwCreateWindow (hidden, OpenGL 3.3 core): " + glfw_last_error;
        if (glfw_users == 0) glfwTerminate();
        return nullptr;
    }
    ++glfw_users;
    return std::make_unique<GlfwContext>(window);
}

}  // namespace o3d::visualization
