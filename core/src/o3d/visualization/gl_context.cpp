// SPDX-License-Identifier: MIT
#include "o3d/visualization/gl_context.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::visualization {

std::unique_ptr<GLContext> create_gl_context(Backend backend) {
    if (backend != Backend::Auto && backend != Backend::Egl && backend != Backend::Glfw)
        throw InvalidArgument("unknown render backend " + std::to_string(int(backend)));
    std::string why_egl, why_glfw;
    if (backend != Backend::Glfw)
        if (auto context = create_egl_context(&why_egl)) return context;
    if (backend != Backend::Egl)
        if (auto context = create_glfw_context(&why_glfw)) return context;
    std::string message = "no OpenGL 3.3 context:";
    if (backend != Backend::Glfw) message += " EGL: " + why_egl + ";";
    if (backend != Backend::Egl) message += " GLFW: " + why_glfw + ";";
    message.pop_back();
    throw Unsupported(message);
}

}  // namespace o3d::visualization
