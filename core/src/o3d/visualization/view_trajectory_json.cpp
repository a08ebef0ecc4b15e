// SPDX-License-Identifier: MIT
// Open3D's ViewTrajectory JSON (what its viewer copies to the clipboard with Ctrl+C), through nlohmann_json.
#include <nlohmann/json.hpp>

#include "o3d/utility/error.h"
#include "o3d/visualization/view_control.h"

namespace o3d::visualization {
namespace {

using nlohmann::json;

Eigen::Vector3d vec3(const json& j, const char* key) {
    const json& v = j.at(key);
    if (!v.is_array() || v.size() != 3) throw ParseError(std::string("ViewTrajectory: \"") + key + "\" must be 3 numbers");
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) out[i] = v.at(size_t(i)).get<double>();
    return out;
}

json array3(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

}  // namespace

ViewTrajectory view_trajectory_from_json(const std::string& text) {
    ViewTrajectory t;
    try {
        const json j = json::parse(text);
        if (!j.is_object() || j.value("class_name", std::string()) != "ViewTrajectory")
            throw ParseError("not a ViewTrajectory (\"class_name\" must be \"ViewTrajectory\")");
        t.interval = j.value("interval", 29);
        t.is_loop = j.value("is_loop", false);
        if (t.interval < 0 || t.interval > 100000) throw ParseError("ViewTrajectory: \"interval\" out of range");
        for (const json& v : j.at("trajectory")) {
            ViewStatus s;
            s.box.min_bound = vec3(v, "boundingbox_min");
            s.box.max_bound = vec3(v, "boundingbox_max");
            s.field_of_view = v.at("field_of_view").get<double>();
            s.zoom = v.at("zoom").get<double>();
            s.lookat = vec3(v, "lookat");
            s.front = vec3(v, "front");
            s.up = vec3(v, "up");
            // The same checks a view gets when set: a file cannot hold a view the viewer would refuse.
            try {
                view_from_lookat(s.lookat, s.front, s.up, s.zoom, s.box, 64, 64, s.field_of_view);
            } catch (const InvalidArgument& e) {
                throw ParseError(std::string("ViewTrajectory: ") + e.what());
            }
            t.views.push_back(s);
        }
    } catch (const json::exception& e) {
        throw ParseError(std::string("ViewTrajectory JSON: ") + e.what());
    }
    if (t.views.empty()) throw ParseError("ViewTrajectory: \"trajectory\" is empty");
    return t;
}

std::string view_trajectory_to_json(const ViewTrajectory& t) {
    json views = json::array();
    for (const ViewStatus& s : t.views)
        views.push_back({{"boundingbox_max", array3(s.box.max_bound)}, {"boundingbox_min", array3(s.box.min_bound)},
                         {"field_of_view", s.field_of_view}, {"front", array3(s.front)}, {"lookat", array3(s.lookat)},
                         {"up", array3(s.up)}, {"zoom", s.zoom}});
    const json j = {{"class_name", "ViewTrajectory"}, {"interval", t.interval}, {"is_loop", t.is_loop},
                    {"trajectory", views}, {"version_major", 1}, {"version_minor", 0}};
    return j.dump(1, '\t');
}

}  // namespace o3d::visualization
