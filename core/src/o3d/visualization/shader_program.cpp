// SPDX-License-Identifier: MIT
#include "o3d/visualization/shader_program.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

// Variant constants (COLOR_MODE, LIT, NORMAL_LINES) are prepended; see shader_program.h for why.
const char* const kVertexShader = R"(
#define COLOR_VARYING (COLOR_MODE != 1)
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
uniform mat4 mvp;
#if NORMAL_LINES
uniform float normal_line_length;
#endif
#if LIT
out vec3 v_world;
out vec3 v_normal;
#endif
#if COLOR_VARYING
out vec3 v_color;
#endif

#if COLOR_MODE >= 2 && COLOR_MODE <= 4
uniform vec3 box_min;
uniform vec3 box_max;
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
#endif

void main() {
#if NORMAL_LINES
    vec3 p = position + normal * (normal_line_length * float(gl_VertexID % 2));
#else
    vec3 p = position;
#endif
    gl_Position = mvp * vec4(p, 1.0);
#if LIT
    v_world = p;
    v_normal = normal;
#endif
#if COLOR_MODE == 0 || COLOR_MODE == 6
    v_color = color;
#elif COLOR_MODE >= 2 && COLOR_MODE <= 4
    v_color = jet(percentage(COLOR_MODE - 2, position));
#elif COLOR_MODE == 5
    v_color = normal * 0.5 + 0.5;
#endif
}
)";

const char* const kFragmentShader = R"(
#define COLOR_VARYING (COLOR_MODE != 1)
#if COLOR_VARYING
in vec3 v_color;
#else
uniform vec3 uniform_color;
#endif
#if COLOR_MODE == 6
uniform sampler2D image;
#endif
uniform vec4 base_color;
#if LIT
in vec3 v_world;
in vec3 v_normal;
uniform vec3 eye;
uniform vec3 ambient;
uniform vec3 light_position[4];
uniform vec3 light_color[4];
uniform float light_diffuse[4];
uniform float light_specular[4];
uniform float light_shininess[4];
#endif
out vec4 frag_color;

void main() {
#if COLOR_MODE == 6
    vec3 c = texture(image, v_color.xy).rgb;
#elif COLOR_VARYING
    vec3 c = v_color * base_color.rgb;
#else
    vec3 c = uniform_color * base_color.rgb;
#endif
#if LIT
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
#endif
    frag_color = vec4(clamp(c, 0.0, 1.0), 1.0);
}
)";

GLuint compile(GLenum type, const std::string& header, const char* body) {
    const GLuint shader = glCreateShader(type);
    const char* parts[2] = {header.c_str(), body};
    glShaderSource(shader, 2, parts, nullptr);
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

ShaderProgram build_shader_program(const ShaderVariant& variant) {
    const std::string header = "#version 330 core\n#define COLOR_MODE " + std::to_string(int(variant.color)) +
                               "\n#define LIT " + (variant.lit ? "1" : "0") + "\n#define NORMAL_LINES " +
                               (variant.normal_lines ? "1" : "0") + "\n";
    const GLuint vs = compile(GL_VERTEX_SHADER, header, kVertexShader);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, header, kFragmentShader);
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
    p.uniform_color = at("uniform_color");
    p.box_min = at("box_min");
    p.box_max = at("box_max");
    p.eye = at("eye");
    p.ambient = at("ambient");
    p.base_color = at("base_color");
    p.light_position = at("light_position");
    p.light_color = at("light_color");
    p.light_diffuse = at("light_diffuse");
    p.light_specular = at("light_specular");
    p.light_shininess = at("light_shininess");
    glUseProgram(p.id);
    glUniform1i(at("image"), 0);  // texture unit 0
    glUseProgram(0);
    return p;
}

const ShaderProgram& ShaderPrograms::get(const ShaderVariant& variant) {
    const auto it = built_.find(variant.key());
    if (it != built_.end()) return it->second;
    return built_.emplace(variant.key(), build_shader_program(variant)).first->second;
}

void ShaderPrograms::release() {
    for (auto& entry : built_) glDeleteProgram(entry.second.id);
    built_.clear();
}

}  // namespace o3d::visualization
