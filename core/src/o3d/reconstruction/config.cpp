// SPDX-License-Identifier: MIT
// JSON goes through nlohmann_json; this file maps Open3D's config keys onto Config and checks their values.
#include "o3d/reconstruction/config.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "o3d/io/file_bytes.h"
#include "o3d/utility/error.h"

namespace o3d::reconstruction {
namespace {

using nlohmann::json;

/// @brief Reads keys of one config object, naming the file and the key in every error.
class Reader {
public:
    Reader(const json& object, const std::string& name) : object_(object), name_(name) {}

    [[noreturn]] void fail(const char* key, const std::string& reason) const {
        throw ParseError(name_ + ": \"" + key + "\": " + reason);
    }
    const json* find(const char* key) const {
        const auto it = object_.find(key);
        return it == object_.end() || it->is_null() ? nullptr : &*it;
    }
    void text(const char* key, std::string& out) const {
        if (const json* v = find(key)) {
            if (!v->is_string()) fail(key, "expected a string");
            out = v->get<std::string>();
        }
    }
    void flag(const char* key, bool& out) const {
        if (const json* v = find(key)) {
            if (!v->is_boolean()) fail(key, "expected true or false");
            out = v->get<bool>();
        }
    }
    /// A finite number above `above` (or at least it, with `inclusive`).
    void number(const char* key, double& out, double above, bool inclusive = false) const {
        if (const json* v = find(key)) {
            if (!v->is_number()) fail(key, "expected a number");
            out = v->get<double>();
        }
        if (!std::isfinite(out) || out < above || (!inclusive && out == above))
            fail(key, std::string("must be finite and ") + (inclusive ? ">= " : "> ") + format(above));
    }
    void integer(const char* key, int& out, int at_least) const {
        if (const json* v = find(key)) {
            if (!v->is_number_integer()) fail(key, "expected an integer");
            const auto x = v->get<int64_t>();
            if (x < at_least || x > std::numeric_limits<int>::max())
                fail(key, "must be an integer >= " + std::to_string(at_least));
            out = static_cast<int>(x);
        }
    }

private:
    static std::string format(double x) {
        std::string s = std::to_string(x);
        s.erase(s.find_last_not_of('0') + 1);
        if (!s.empty() && s.back() == '.') s.pop_back();
        return s;
    }
    const json& object_;
    const std::string& name_;
};

/// @brief The one printf integer field of a fragment template: where it is, its width, zero padding.
struct IdField {
    size_t begin = 0, end = 0;
    int width = 0;
    bool zero = false;
};

/// @brief Parse "%d", "%3d" or "%03d"; any other '%' (or none, or two) is an error: the template is
/// filled by this library, not handed to printf.
bool find_id_field(const std::string& t, IdField& field) {
    int fields = 0;
    for (size_t i = 0; i < t.size(); ++i) {
        if (t[i] != '%') continue;
        size_t j = i + 1;
        IdField f;
        f.begin = i;
        if (j < t.size() && t[j] == '0') f.zero = true, ++j;
        while (j < t.size() && std::isdigit(static_cast<unsigned char>(t[j])) && f.width < 100)
            f.width = f.width * 10 + (t[j++] - '0');
        if (j >= t.size() || t[j] != 'd') return false;
        f.end = j + 1;
        field = f;
        ++fields;
        i = j;
    }
    return fields == 1;
}

}  // namespace

std::string Config::output(const std::string& relative) const {
    const std::string& root = path_output.empty() ? path_dataset : path_output;
    return (std::filesystem::path(root) / relative).string();
}

std::string Config::fragment_output(const std::string& fragment_template, int id) const {
    IdField f;
    if (!find_id_field(fragment_template, f))
        throw InvalidArgument("fragment template \"" + fragment_template + "\" needs exactly one %d field");
    std::string digits = std::to_string(id);
    if (static_cast<int>(digits.size()) < f.width)
        digits.insert(0, static_cast<size_t>(f.width) - digits.size(), f.zero ? '0' : ' ');
    return output(fragment_template.substr(0, f.begin) + digits + fragment_template.substr(f.end));
}

Config parse_config(std::string_view text, const std::string& name) {
    json root;
    try {
        root = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        throw ParseError(name + ": invalid JSON: " + e.what());
    }
    if (!root.is_object()) throw ParseError(name + ": expected a JSON object");
    const Reader r(root, name);
    Config c;
    r.text("path_dataset", c.path_dataset);
    if (c.path_dataset.empty()) r.fail("path_dataset", "required: the folder with the colour and depth images");
    r.text("path_intrinsic", c.path_intrinsic);
    r.text("path_output", c.path_output);
    r.number("depth_scale", c.depth_scale, 0.0);
    r.number("depth_min", c.depth_min, 0.0, true);
    if (r.find("max_depth") && !r.find("depth_max")) r.number("max_depth", c.depth_max, 0.0);
    r.number("depth_max", c.depth_max, 0.0);
    r.number("voxel_size", c.voxel_size, 0.0);
    r.number("depth_diff_max", c.depth_diff_max, 0.0);
    r.integer("n_frames_per_fragment", c.n_frames_per_fragment, 1);
    r.integer("n_keyframes_per_n_frame", c.n_keyframes_per_n_frame, 1);
    r.number("preference_loop_closure_odometry", c.preference_loop_closure_odometry, 0.0);
    r.number("preference_loop_closure_registration", c.preference_loop_closure_registration, 0.0);
    r.number("tsdf_cubic_size", c.tsdf_cubic_size, 0.0);
    r.text("icp_method", c.icp_method);
    if (c.icp_method != "point_to_point" && c.icp_method != "point_to_plane" && c.icp_method != "color" &&
        c.icp_method != "generalized")
        r.fail("icp_method", "expected point_to_point, point_to_plane, color or generalized");
    r.text("global_registration", c.global_registration);
    if (c.global_registration != "ransac" && c.global_registration != "fgr")
        r.fail("global_registration", "expected ransac or fgr");
    r.flag("python_multi_threading", c.python_multi_threading);
    r.flag("loop_closure_odometry", c.loop_closure_odometry);
    r.integer("color_map_maximum_iteration", c.color_map_maximum_iteration, 0);

    struct Template {
        const char* key;
        std::string* value;
        bool per_fragment;
    };
    const Template templates[] = {
        {"template_fragment_posegraph", &c.template_fragment_posegraph, true},
        {"template_fragment_posegraph_optimized", &c.template_fragment_posegraph_optimized, true},
        {"template_fragment_pointcloud", &c.template_fragment_pointcloud, true},
        {"template_global_posegraph", &c.template_global_posegraph, false},
        {"template_global_posegraph_optimized", &c.template_global_posegraph_optimized, false},
        {"template_refined_posegraph", &c.template_refined_posegraph, false},
        {"template_refined_posegraph_optimized", &c.template_refined_posegraph_optimized, false},
        {"template_global_mesh", &c.template_global_mesh, false},
        {"template_global_traj", &c.template_global_traj, false},
        {"template_color_map_mesh", &c.template_color_map_mesh, false},
    };
    for (const Template& t : templates) {
        r.text(t.key, *t.value);
        IdField f;
        if (t.value->empty()) r.fail(t.key, "must not be empty");
        if (t.per_fragment && !find_id_field(*t.value, f)) r.fail(t.key, "needs exactly one %d field");
        if (!t.per_fragment && t.value->find('%') != std::string::npos) r.fail(t.key, "must not contain '%'");
    }
    return c;
}

Config read_config(const std::string& path) {
    const io::detail::FileBytes bytes(path);
    return parse_config(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
}

}  // namespace o3d::reconstruction
