// SPDX-License-Identifier: MIT
#include "o3d/visualization/shader_program.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
uniform mat4 mvp;
uniform float normal_line_length;  // > 0: odd vertices are moved along the normal (point_show_normal)
uniform int color_mode;
uniform vec3 uniform_color;
uniform vec3 box_min;
uniform vec3 box_max;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;

// Open3D's ColorMapJet: each channel is a trapezoid over [0, 1].
float jet_base(float v) {
    if (v <= -0.75) return 0.0;
    if (v <= -0.25) return (v + 0.75) * 2.0;
    if (v <= 0.25) return 1.0;
    if (v <= 0.75) return 1.0 - (v - 0.25) * 2.0;
    return 0.0;
}
vec3 jet(float t) { return vec3(jet_base(t * 2.0 - 1.5), jet_base(t * 2.0 - 1.0), jet_base(t * 2.0 - 0.5)); }
float percentage(int axis, vec3 p) {
    float extent = box_max[axis] - box_min[axis];
    return extent > 0.0 ? (p[axis] - box_min[axis]) / extent : 0.5;
}

void main() {
    vec3 p = position + normal * (normal_line_length * float(gl_VertexID % 2));
    gl_Position = mvp * vec4(p, 1.0);
    v_world = p;
    v_normal = normal;
    if (color_mode == 0 || color_mode == 6) v_color = color;
    else if (color_mode == 1) v_color = uniform_color;
    else if (color_mode <= 4) v_color = jet(percentage(color_mode - 2, position));
    else v_color = normal * 0.5 + 0.5;
}
)";

const char* const kFragmentShader = R"(#version 330 core
in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
uniform int lit;
uniform int textured;
uniform sampler2D image;
uniform vec3 eye;
uniform vec3 ambient;
uniform vec4 base_color;
uniform vec3 light_position[4];
uniform vec3 light_color[4];
uniform float light_diffuse[4];
uniform float light_specular[4];
uniform float light_shininess[4];
out vec4 frag_color;

void main() {
    vec3 c = textured != 0 ? texture(image, v_color.xy).rgb : v_color * base_color.rgb;
    if (lit != 0) {
        vec3 n = normalize(v_normal);
        if (!gl_FrontFacing) n = -n;  // a back face shown (mesh_show_back_face) is lit from its side
        vec3 to_eye = normalize(eye - v_world);
        vec3 diffuse = ambient;
        vec3 specular = vec3(0.0);
        for (int i = 0; i < 4; ++i) {
            vec3 l = normalize(light_position[i] - v_world);
            diffuse += light_diffuse[i] * max(dot(n, l), 0.0) * light_color[i];
            vec3 r = reflect(-l, n);
            specular += light_specular[i] * pow(max(dot(r, to_eye), 0.0), light_shininess[i]) * light_color[i];
        }
        c = c * diffuse + specular;
    }
    frag_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
)";

GLuint compile(GLenum type, const char* source) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {0};
        glGetShaderInfoLog(shader, sizeof log - 1, nullptr, log);
        glDeleteShader(shader);
        throw Unsupported(std::string("the OpenGL driver cannot compile o3d's shader: ") + log);
    }
    return shader;
}

}  // namespace

ShaderProgram build_shader_program() {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    ShaderProgram p;
    p.id = glCreateProgram();
    glAttachShader(p.id, vs);
    glAttachShader(p.id, fs);
    glLinkProgram(p.id);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p.id, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {0};
        glGetProgramInfoLog(p.id, sizeof log - 1, nullptr, log);
        glDeleteProgram(p.id);
        throw Unsupported(std::string("the OpenGL driver cannot link o3d's shader: ") + log);
    }
    auto at = [&](const char* name) { return glGetUniformLocation(p.id, name); };
    p.mvp = at("mvp");
    p.normal_line_length = at("normal_line_length");
    p.color_mode = at("color_mode");
    p.uniform_color = at("uniform_color");
    p.box_min = at("box_min");
    p.box_max = at("box_max");
    p.lit = at("lit");
    p.eye = at("eye");
    p.ambient = at("ambient");
    p.base_color = at("base_color");
    p.textured = at("textured");
    p.light_position = at("light_position");
    p.light_color = at("light_color");
    p.light_diffuse = at("light_diffuse");
    p.light_specular = at("light_specular");
    p.light_shininess = at("light_shininess");
    return p;
}

}  // namespace o3d::visualization
