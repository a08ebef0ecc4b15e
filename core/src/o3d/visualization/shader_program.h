// SPDX-License-Identifier: MIT
#pragma once
/// @file shader_program.h
/// @brief The GLSL programs geometries are drawn with: Open3D's Phong lighting with four lights, its color
/// options (attribute, uniform, Jet map of x/y/z, normal), point-normal lines and flat images.
///
/// One source, compiled per variant (color mode, lit or not, normal lines or not) with the choices as
/// preprocessor constants: a software rasterizer (llvmpipe, the only one on a server without a GPU) pays
/// per vertex and per fragment for every branch and every interpolated value a program has, even ones a
/// uniform switches off, so an unlit colored cloud gets a program that only moves points and passes colors.
#include <epoxy/gl.h>

#include <map>

namespace o3d::visualization {

/// @brief How a vertex gets its color.
/// Texture: the color attribute holds texture coordinates into `image` (images shown flat).
enum class ColorMode { Attribute = 0, Uniform = 1, JetX = 2, JetY = 3, JetZ = 4, Normal = 5, Texture = 6 };

/// @brief What a program is compiled for.
struct ShaderVariant {
    ColorMode color = ColorMode::Attribute;
    bool lit = false;
    bool normal_lines = false;  ///< odd vertices moved along the normal by `normal_line_length`
    int key() const { return int(color) * 4 + (lit ? 2 : 0) + (normal_lines ? 1 : 0); }
};

/// @brief A linked program and its uniforms' locations (-1 where the variant has no such uniform, which
/// glUniform* ignores).
struct ShaderProgram {
    GLuint id = 0;
    GLint mvp = -1, normal_line_length = -1, uniform_color = -1, box_min = -1, box_max = -1;
    GLint eye = -1, ambient = -1, base_color = -1;
    GLint light_position = -1, light_color = -1, light_diffuse = -1, light_specular = -1, light_shininess = -1;
};

/// @brief Compiles and links a variant in the current context; throws o3d::Unsupported with the driver's log
/// when it fails.
ShaderProgram build_shader_program(const ShaderVariant& variant);

/// @brief The variants one context has built, each compiled on first use.
class ShaderPrograms {
public:
    const ShaderProgram& get(const ShaderVariant& variant);
    /// @brief Deletes every program; the context must be current.
    void release();

private:
    std::map<int, ShaderProgram> built_;
};

}  // namespace o3d::visualization
