// SPDX-License-Identifier: MIT
// RenderOption checks and its JSON form. JSON goes through nlohmann_json; this file maps Open3D's keys
// (RenderOption::ConvertToJsonValue / ConvertFromJsonValue: "light0_position", "point_color_option", ...).
#include "o3d/visualization/render_option.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

using nlohmann::json;

bool finite3(const Eigen::Vector3d& v) { return v.allFinite(); }

void check_range(double value, double lo, double hi, const char* name) {
    if (!(value >= lo && value <= hi))
        throw InvalidArgument(std::string(name) + " must be in [" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "], got " + std::to_string(value));
}

void check_unit_color(const Eigen::Vector3d& c, const char* name) {
    for (int k = 0; k < 3; ++k) check_range(c[k], 0.0, 1.0, name);
}

struct Reader {
    const json& root;
    const std::string& path;

    [[noreturn]] void fail(const std::string& key, const std::string& why) const {
        throw ParseError(path + ": \"" + key + "\" " + why);
    }
    const json* find(const std::string& key) const {
        const auto it = root.find(key);
        return it == root.end() ? nullptr : &*it;
    }
    void number(const std::string& key, double& out) const {
        if (const json* v = find(key)) {
            if (!v->is_number()) fail(key, "is not a number");
            out = v->get<double>();
        }
    }
    void boolean(const std::string& key, bool& out) const {
        if (const json* v = find(key)) {
            if (v->is_boolean()) out = v->get<bool>();
            else if (v->is_number_integer()) out = v->get<int64_t>() != 0;
            else fail(key, "is not a boolean");
        }
    }
    void vec3(const std::string& key, Eigen::Vector3d& out) const {
        if (const json* v = find(key)) {
            if (!v->is_array() || v->size() != 3) fail(key, "is not an array of 3 numbers");
            for (int k = 0; k < 3; ++k) {
                if (!(*v)[k].is_number()) fail(key, "is not an array of 3 numbers");
                out[k] = (*v)[k].get<double>();
            }
        }
    }
    void integer(const std::string& key, int& out) const {
        if (const json* v = find(key)) {
            if (!v->is_number_integer()) fail(key, "is not an integer");
            const int64_t x = v->get<int64_t>();
            if (x < -1000 || x > 1000) fail(key, "is out of range");
            out = static_cast<int>(x);
        }
    }
};

json vec3_json(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

}  // namespace

bool is_color_option(int value) { return (value >= 0 && value <= 4) || value == 9; }

void check_render_option(const RenderOption& o) {
    check_unit_color(o.background_color, "background_color");
    check_range(o.point_size, 1.0, 25.0, "point_size");
    check_range(o.line_width, 1.0, 10.0, "line_width");
    if (o.mesh_shade != MeshShade::Flat && o.mesh_shade != MeshShade::Smooth)
        throw InvalidArgument("mesh_shade_option must be 0 (flat) or 1 (smooth)");
    if (!is_color_option(int(o.point_color))) throw InvalidArgument("point_color_option must be 0-4 or 9");
    if (!is_color_option(int(o.mesh_color))) throw InvalidArgument("mesh_color_option must be 0-4 or 9");
    check_unit_color(o.default_mesh_color, "default_mesh_color");
    check_unit_color(o.light_ambient_color, "light_ambient_color");
    for (const Light& light : o.lights) {
        if (!finite3(light.position)) throw InvalidArgument("light_position must be finite");
        check_unit_color(light.color, "light_color");
        check_range(light.diffuse_power, 0.0, 100.0, "light_diffuse_power");
        check_range(light.specular_power, 0.0, 100.0, "light_specular_power");
        check_range(light.specular_shininess, 0.0, 1e4, "light_specular_shininess");
    }
}

void check_material(const Material& m) {
    if (m.shader != Shader::DefaultLit && m.shader != Shader::DefaultUnlit)
        throw InvalidArgument("material shader must be O3D_SHADER_DEFAULT_LIT or O3D_SHADER_DEFAULT_UNLIT");
    for (int k = 0; k < 4; ++k) check_range(m.base_color[k], 0.0, 1.0, "material base_color");
    if (m.point_size != 0) check_range(m.point_size, 1.0, 25.0, "material point_size (0 = the RenderOption's)");
    if (m.line_width != 0) check_range(m.line_width, 1.0, 10.0, "material line_width (0 = the RenderOption's)");
}

void load_render_option_json(const std::string& path, RenderOption& option) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError("cannot open " + path);
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) throw IoError("cannot read " + path);
    json root;
    try {
        root = json::parse(text.str());
    } catch (const json::exception& e) {
        throw ParseError(path + ": invalid JSON: " + e.what());
    }
    if (!root.is_object()) throw ParseError(path + ": expected a JSON object");
    const Reader r{root, path};
    if (const json* name = r.find("class_name"); name && (!name->is_string() || *name != "RenderOption"))
        r.fail("class_name", "is not \"RenderOption\"");

    RenderOption o = option;  // filled fully, then checked, then committed: a bad file changes nothing
    r.vec3("background_color", o.background_color);
    r.number("point_size", o.point_size);
    r.number("line_width", o.line_width);
    r.boolean("light_on", o.light_on);
    r.boolean("point_show_normal", o.point_show_normal);
    r.boolean("mesh_show_wireframe", o.mesh_show_wireframe);
    r.boolean("mesh_show_back_face", o.mesh_show_back_face);
    int shade = int(o.mesh_shade), point_color = int(o.point_color), mesh_color = int(o.mesh_color);
    r.integer("mesh_shade_option", shade);
    r.integer("point_color_option", point_color);
    r.integer("mesh_color_option", mesh_color);
    o.mesh_shade = MeshShade(shade);
    o.point_color = ColorOption(point_color);
    o.mesh_color = ColorOption(mesh_color);
    r.vec3("default_mesh_color", o.default_mesh_color);
    r.vec3("light_ambient_color", o.light_ambient_color);
    for (int i = 0; i < 4; ++i) {
        const std::string p = "light" + std::to_string(i) + "_";
        r.vec3(p + "position", o.lights[i].position);
        r.vec3(p + "color", o.lights[i].color);
        r.number(p + "diffuse_power", o.lights[i].diffuse_power);
        r.number(p + "specular_power", o.lights[i].specular_power);
        r.number(p + "specular_shininess", o.lights[i].specular_shininess);
    }
    try {
        check_render_option(o);
    } catch (const InvalidArgument& e) {
        throw ParseError(path + ": " + e.what());
    }
    option = o;
}

void save_render_option_json(const std::string& path, const RenderOption& o) {
    json root = {
        {"class_name", "RenderOption"},
        {"version_major", 1},
        {"version_minor", 0},
        {"background_color", vec3_json(o.background_color)},
        {"point_size", o.point_size},
        {"line_width", o.line_width},
        {"light_on", o.light_on},
        {"point_show_normal", o.point_show_normal},
        {"mesh_show_wireframe", o.mesh_show_wireframe},
        {"mesh_show_back_face", o.mesh_show_back_face},
        {"mesh_shade_option", int(o.mesh_shade)},
        {"point_color_option", int(o.point_color)},
        {"mesh_color_option", int(o.mesh_color)},
        {"default_mesh_color", vec3_json(o.default_mesh_color)},
        {"light_ambient_color", vec3_json(o.light_ambient_color)},
    };
    for (int i = 0; i < 4; ++i) {
        const std::string p = "light" + std::to_string(i) + "_";
        root[p + "position"] = vec3_json(o.lights[i].position);
        root[p + "color"] = vec3_json(o.lights[i].color);
        root[p + "diffuse_power"] = o.lights[i].diffuse_power;
        root[p + "specular_power"] = o.lights[i].specular_power;
        root[p + "specular_shininess"] = o.lights[i].specular_shininess;
    }
    std::ofstream out(path, std::ios::binary);
    if (!out) throw IoError("cannot open " + path + " for writing");
    out << root.dump(1, '\t') << "\n";
    if (!out) throw IoError("cannot write " + path);
}

}  // namespace o3d::visualization
