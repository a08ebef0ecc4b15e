// SPDX-License-Identifier: MIT
#pragma once
/// @file gl_context.h
/// @brief An OpenGL 3.3 core context with no window to show: EGL (headless) or a hidden GLFW window.
#include <memory>
#include <string>

namespace o3d::visualization {

enum class Backend { Auto = 0, Egl = 1, Glfw = 2 };

/// @brief Owns a context; make_current() binds it to the calling thread until release().
class GLContext {
public:
    virtual ~GLContext() = default;
    virtual void make_current() = 0;
    virtual void release() = 0;
    virtual Backend backend() const = 0;
};

/// @brief The first backend that gives a context (Auto: EGL, then GLFW). Throws Unsupported naming what
/// each backend answered.
std::unique_ptr<GLContext> create_gl_context(Backend backend);

/// @brief Binds a context for one scope.
class CurrentContext {
public:
    explicit CurrentContext(GLContext& context) : context_(context) { context_.make_current(); }
    ~CurrentContext() { context_.release(); }
    CurrentContext(const CurrentContext&) = delete;
    CurrentContext& operator=(const CurrentContext&) = delete;

private:
    GLContext& context_;
};

// Per backend (gl_context_egl.cpp, gl_context_glfw.cpp): nullptr with `why` filled when unavailable.
std::unique_ptr<GLContext> create_egl_context(std::string* why);
std::unique_ptr<GLContext> create_glfw_context(std::string* why);

}  // namespace o3d::visualization
