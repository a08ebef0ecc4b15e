// SPDX-License-Identifier: MIT
#pragma once
/// @file shader_program.h
/// @brief The one GLSL program every geometry is drawn with: Open3D's Phong lighting with four lights,
/// its color options (attribute, uniform, Jet map of x/y/z, normal), and point-normal lines.
#include <epoxy/gl.h>

namespace o3d::visualization {

/// @brief How a vertex gets its color (the `color_mode` uniform).
/// Texture: the color attribute holds texture coordinates into `image` (images shown flat).
enum class ColorMode { Attribute = 0, Uniform = 1, JetX = 2, JetY = 3, JetZ = 4, Normal = 5, Texture = 6 };

struct ShaderProgram {
    GLuint id = 0;
    GLint mvp = -1, normal_line_length = -1, color_mode = -1, uniform_color = -1, box_min = -1, box_max = -1;
    GLint lit = -1, eye = -1, ambient = -1, base_color = -1, textured = -1;
    GLint light_position = -1, light_color = -1, light_diffuse = -1, light_specular = -1, light_shininess = -1;
};

/// @brief Compiles and links the program in the current context; throws o3d::Unsupported with the
/// driver's log when it fails.
ShaderProgram build_shader_program();

}  // namespace o3d::visualization
