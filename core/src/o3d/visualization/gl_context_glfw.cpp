// SPDX-License-Identifier: MIT
// The fallback when EGL gives nothing: a hidden GLFW window (an X display is needed, e.g. Xvfb).
// libglfw is opened at run time, like libEGL: linking it would make libo3d need libX11 everywhere,
// headless servers and slim containers included, for a path they never take.
#include <dlfcn.h>
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // types and constants only: every function comes through dlsym

#include <mutex>
#include <string>

#include "o3d/visualization/gl_context.h"

namespace o3d::visualization {
namespace {

/// @brief The GLFW functions o3d uses, from libglfw.so.3.
struct GlfwApi {
    decltype(&::glfwInit) init = nullptr;
    decltype(&::glfwTerminate) terminate = nullptr;
    decltype(&::glfwSetErrorCallback) set_error_callback = nullptr;
    decltype(&::glfwDefaultWindowHints) default_window_hints = nullptr;
    decltype(&::glfwWindowHint) window_hint = nullptr;
    decltype(&::glfwCreateWindow) create_window = nullptr;
    decltype(&::glfwDestroyWindow) destroy_window = nullptr;
    decltype(&::glfwMakeContextCurrent) make_context_current = nullptr;
    std::string missing;  ///< why it is unusable; empty when every function was found
};

const GlfwApi& glfw() {
    static const GlfwApi api = [] {
        GlfwApi a;
        void* lib = dlopen("libglfw.so.3", RTLD_NOW | RTLD_LOCAL);  // kept for the process
        if (!lib) {
            a.missing = "libglfw.so.3 not found";
            return a;
        }
        auto load = [&](auto& fn, const char* name) {
            fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(lib, name));
            if (!fn && a.missing.empty()) a.missing = std::string("libglfw.so.3 lacks ") + name;
        };
        load(a.init, "glfwInit");
        load(a.terminate, "glfwTerminate");
        load(a.set_error_callback, "glfwSetErrorCallback");
        load(a.default_window_hints, "glfwDefaultWindowHints");
        load(a.window_hint, "glfwWindowHint");
        load(a.create_window, "glfwCreateWindow");
        load(a.destroy_window, "glfwDestroyWindow");
        load(a.make_context_current, "glfwMakeContextCurrent");
        return a;
    }();
    return api;
}

std::mutex glfw_mutex;  // guards the count of live windows: GLFW is initialised while any exists
int glfw_users = 0;
thread_local std::string glfw_last_error;

void remember_error(int, const char* description) { glfw_last_error = description ? description : "?"; }

class GlfwContext final : public GLContext {
public:
    explicit GlfwContext(GLFWwindow* window) : window_(window) {}
    ~GlfwContext() override {
        std::lock_guard<std::mutex> lock(glfw_mutex);
        glfw().destroy_window(window_);
        if (--glfw_users == 0) glfw().terminate();
    }
    void make_current() override { glfw().make_context_current(window_); }
    void release() override { glfw().make_context_current(nullptr); }
    Backend backend() const override { return Backend::Glfw; }

private:
    GLFWwindow* window_;
};

}  // namespace

std::unique_ptr<GLContext> create_glfw_context(std::string* why) {
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
    std::lock_guard<std::mutex> lock(glfw_mutex);
    api.set_error_callback(remember_error);
    if (glfw_users == 0 && !api.init()) {
        *why = "glfwInit: " + glfw_last_error;
        return nullptr;
    }
    api.default_window_hints();
    api.window_hint(GLFW_VISIBLE, GLFW_FALSE);
    api.window_hint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    api.window_hint(GLFW_CONTEXT_VERSION_MINOR, 3);
    api.window_hint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    api.window_hint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);  // wide lines stay allowed
    GLFWwindow* window = api.create_window(16, 16, "o3d", nullptr, nullptr);
    if (!window) {
        *why = "glfwCreateWindow (hidden, OpenGL 3.3 core): " + glfw_last_error;
        if (glfw_users == 0) api.terminate();
        return nullptr;
    }
    ++glfw_users;
    return std::make_unique<GlfwContext>(window);
}

}  // namespace o3d::visualization
