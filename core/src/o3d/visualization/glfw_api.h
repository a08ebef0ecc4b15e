// SPDX-License-Identifier: MIT
#pragma once
/// @file glfw_api.h
/// @brief The GLFW functions o3d uses, resolved from libglfw.so.3 at run time. Linking libglfw would make
/// libo3d need libX11 everywhere, headless servers and slim containers included, for windows they never open.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // types and constants only: every function comes through dlsym

#include <mutex>
#include <string>

namespace o3d::visualization {

struct GlfwApi {
    decltype(&::glfwInit) init = nullptr;
    decltype(&::glfwTerminate) terminate = nullptr;
    decltype(&::glfwSetErrorCallback) set_error_callback = nullptr;
    decltype(&::glfwDefaultWindowHints) default_window_hints = nullptr;
    decltype(&::glfwWindowHint) window_hint = nullptr;
    decltype(&::glfwCreateWindow) create_window = nullptr;
    decltype(&::glfwDestroyWindow) destroy_window = nullptr;
    decltype(&::glfwMakeContextCurrent) make_context_current = nullptr;
    decltype(&::glfwSetWindowPos) set_window_pos = nullptr;
    decltype(&::glfwShowWindow) show_window = nullptr;
    decltype(&::glfwSwapBuffers) swap_buffers = nullptr;
    decltype(&::glfwSwapInterval) swap_interval = nullptr;
    decltype(&::glfwPollEvents) poll_events = nullptr;
    decltype(&::glfwWaitEventsTimeout) wait_events_timeout = nullptr;
    decltype(&::glfwWindowShouldClose) window_should_close = nullptr;
    decltype(&::glfwSetWindowShouldClose) set_window_should_close = nullptr;
    decltype(&::glfwSetWindowUserPointer) set_window_user_pointer = nullptr;
    decltype(&::glfwGetWindowUserPointer) get_window_user_pointer = nullptr;
    decltype(&::glfwSetKeyCallback) set_key_callback = nullptr;
    decltype(&::glfwSetMouseButtonCallback) set_mouse_button_callback = nullptr;
    decltype(&::glfwSetCursorPosCallback) set_cursor_pos_callback = nullptr;
    decltype(&::glfwSetScrollCallback) set_scroll_callback = nullptr;
    decltype(&::glfwSetWindowRefreshCallback) set_window_refresh_callback = nullptr;
    decltype(&::glfwSetClipboardString) set_clipboard_string = nullptr;
    std::string missing;  ///< why it is unusable; empty when every function was found
};

/// @brief Loaded once per process (the library stays open).
const GlfwApi& glfw();

/// @brief Guards GLFW's initialisation count: GLFW is initialised while any window exists. Window
/// creation, destruction and event processing happen under it or on the thread that owns the windows.
std::mutex& glfw_mutex();

/// @brief glfwInit when no window exists yet (the caller holds glfw_mutex()); false with `why` filled.
bool glfw_acquire(std::string* why);
/// @brief What GLFW last reported on this thread.
std::string glfw_last_error();
/// @brief After destroying a window (the caller holds glfw_mutex()): glfwTerminate with the last one.
void glfw_release();

}  // namespace o3d::visualization
