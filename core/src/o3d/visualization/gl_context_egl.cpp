// SPDX-License-Identifier: MIT
// EGL through libepoxy. libepoxy opens libEGL itself, but aborts the process when it cannot: so libEGL is
// probed with dlopen first, and a machine without it gets an error instead.
#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <string>

#include "o3d/visualization/gl_context.h"

namespace o3d::visualization {
namespace {

std::string egl_error(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
    return std::string(what) + " failed (" + code + ")";
}

class EglContext final : public GLContext {
public:
    EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        // The display is shared by every context of the process (eglGetPlatformDisplay returns the same
        // one), so it is not terminated here.
    }
    void make_current() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }
    void release() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
    Backend backend() const override { return Backend::Egl; }

private:
    EGLDisplay display_;
    EGLContext context_;
};

/// @brief A display that needs no window system: a GPU through EGL_EXT_platform_device, else Mesa's
/// surfaceless platform (software rendering included), else the default display.
EGLDisplay headless_display() {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device") &&
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
            for (EGLint i = 0; i < count; ++i) {
                const char* ext = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
                // Mesa lists a software device too; a real one is preferred, the surfaceless path covers software.
                if (ext && std::string(ext).find("EGL_MESA_device_software") != std::string::npos) continue;
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                EGLint major = 0, minor = 0;
                if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
            }
        }
    }
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint major = 0, minor = 0;
    if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
    return EGL_NO_DISPLAY;
}

}  // namespace

std::unique_ptr<GLContext> create_egl_context(std::string* why) {
    // Kept open for the life of the process: libepoxy holds pointers into it.
    static void* const libegl = dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (!libegl) {
        *why = "libEGL.so.1 not found";
        return nullptr;
    }
    // libepoxy takes OpenGL 1.x entry points from libOpenGL (GLVND) or libGL, and aborts without either.
    static void* const libgl = dlopen("libOpenGL.so.0", RTLD_NOW | RTLD_GLOBAL)
                                   ? reinterpret_cast<void*>(1)
                                   : dlopen("libGL.so.1", RTLD_NOW | RTLD_GLOBAL);
    if (!libgl) {
        *why = "neither libOpenGL.so.0 nor libGL.so.1 found";
        return nullptr;
    }
    const EGLDisplay display = headless_display();
    if (display == EGL_NO_DISPLAY) {
        *why = "no EGL display (tried a GPU device, Mesa's surfaceless platform and the default display)";
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        *why = egl_error("eglBindAPI(EGL_OPENGL_API)");
        return nullptr;
    }
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglChooseConfig(display, config_attributes, &config, 1, &configs);
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    // Without a config, EGL_KHR_no_config_context still allows one: rendering goes to our framebuffer only.
    const EGLContext context =
        eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT) {
        *why = egl_error("eglCreateContext (OpenGL 3.3 core)");
        return nullptr;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        *why = egl_error("eglMakeCurrent without a surface");
        eglDestroyContext(display, context);
        return nullptr;
    }
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    return std::make_unique<EglContext>(display, context);
}

}  // namespace o3d::visualization
