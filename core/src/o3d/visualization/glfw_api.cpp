// SPDX-License-Identifier: MIT
#include "o3d/visualization/glfw_api.h"

#include <dlfcn.h>

#include <type_traits>

namespace o3d::visualization {
namespace {

int glfw_users = 0;  // windows alive, under glfw_mutex()
thread_local std::string last_error;

void remember_error(int, const char* description) { last_error = description ? description : "?"; }

}  // namespace

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
        load(a.set_window_pos, "glfwSetWindowPos");
        load(a.show_window, "glfwShowWindow");
        load(a.swap_buffers, "glfwSwapBuffers");
        load(a.swap_interval, "glfwSwapInterval");
        load(a.poll_events, "glfwPollEvents");
        load(a.wait_events_timeout, "glfwWaitEventsTimeout");
        load(a.window_should_close, "glfwWindowShouldClose");
        load(a.set_window_should_close, "glfwSetWindowShouldClose");
        load(a.set_window_user_pointer, "glfwSetWindowUserPointer");
        load(a.get_window_user_pointer, "glfwGetWindowUserPointer");
        load(a.set_key_callback, "glfwSetKeyCallback");
        load(a.set_mouse_button_callback, "glfwSetMouseButtonCallback");
        load(a.set_cursor_pos_callback, "glfwSetCursorPosCallback");
        load(a.set_scroll_callback, "glfwSetScrollCallback");
        load(a.set_window_refresh_callback, "glfwSetWindowRefreshCallback");
        load(a.set_clipboard_string, "glfwSetClipboardString");
        return a;
    }();
    return api;
}

std::mutex& glfw_mutex() {
    static std::mutex m;
    return m;
}

bool glfw_acquire(std::string* why) {
    const GlfwApi& api = glfw();
    if (!api.missing.empty()) {
        *why = api.missing;
        return false;
    }
    api.set_error_callback(remember_error);
    if (glfw_users == 0 && !api.init()) {
        *why = "glfwInit: " + last_error;
        return false;
    }
    ++glfw_users;
    return true;
}

std::string glfw_last_error() { return last_error; }

void glfw_release() {
    if (--glfw_users == 0) glfw().terminate();
}

}  // namespace o3d::visualization
