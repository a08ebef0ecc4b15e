// SPDX-License-Identifier: MIT
// JSON goes through nlohmann_json; this file only maps Open3D's field names and layouts.
#include "o3d/camera/camera_json_io.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "o3d/camera/camera_checks.h"
#include "o3d/utility/error.h"

namespace o3d::camera {
namespace {

using nlohmann::json;

/// @brief Names the source and, for nested objects, where in it the problem is.
struct Where {
    const std::string& name;
    std::string path;

    [[noreturn]] void fail(const std::string& reason) const {
        throw ParseError(name + ": " + (path.empty() ? "" : path + ": ") + reason);
    }
    Where at(const std::string& key) const { return {name, path.empty() ? key : path + "." + key}; }
};

json parse_text(std::string_view text, const std::string& name) {
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        throw ParseError(name + ": invalid JSON: " + e.what());
    }
}

const json& member(const json& object, const char* key, const Where& where) {
    if (!object.is_object()) where.fail("expected a JSON object");
    const auto it = object.find(key);
    if (it == object.end()) where.fail(std::string("missing \"") + key + "\"");
    return *it;
}

int read_int(const json& object, const char* key, const Where& where) {
    const json& v = member(object, key, where);
    if (!v.is_number_integer()) where.at(key).fail("expected an integer");
    const auto x = v.get<int64_t>();
    if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max())
        where.at(key).fail("integer out of range");
    return static_cast<int>(x);
}

/// @brief `count` finite numbers; the JSON array holds them in column-major order.
void read_numbers(const json& object, const char* key, size_t count, double* out, const Where& where) {
    const json& v = member(object, key, where);
    if (!v.is_array() || v.size() != count)
        where.at(key).fail("expected an array of " + std::to_string(count) + " numbers");
    for (size_t k = 0; k < count; ++k) {
        if (!v[k].is_number()) where.at(key).fail("element " + std::to_string(k) + " is not a number");
        out[k] = v[k].get<double>();
        if (!std::isfinite(out[k])) where.at(key).fail("element " + std::to_string(k) + " is not finite");
    }
}

/// @brief Open3D tags parameters and trajectories with a class name and version 1.0; a missing
/// version counts as 1.0, as in Open3D.
void check_class(const json& object, const char* class_name, const Where& where) {
    const json& cls = member(object, "class_name", where);
    if (!cls.is_string() || cls.get<std::string>() != class_name)
        where.fail(std::string("\"class_name\" is not \"") + class_name + "\"");
    const int major = object.contains("version_major") ? read_int(object, "version_major", where) : 1;
    const int minor = object.contains("version_minor") ? read_int(object, "version_minor", where) : 0;
    if (major != 1 || minor != 0)
        where.fail("unsupported version " + std::to_string(major) + "." + std::to_string(minor) + " (expected 1.0)");
}

PinholeCameraIntrinsic intrinsic_from(const json& object, const Where& where) {
    PinholeCameraIntrinsic in;
    in.width = read_int(object, "width", where);
    in.height = read_int(object, "height", where);
    double m[9];
    read_numbers(object, "intrinsic_matrix", 9, m, where);
    // Column-major 3x3: fx at (0,0), fy at (1,1), cx, cy in the third column.
    in.fx = m[0];
    in.fy = m[4];
    in.cx = m[6];
    in.cy = m[7];
    return in;
}

PinholeCameraParameters parameters_from(const json& object, const Where& where) {
    check_class(object, "PinholeCameraParameters", where);
    PinholeCameraParameters p;
    p.intrinsic = intrinsic_from(member(object, "intrinsic", where), where.at("intrinsic"));
    double e[16];
    read_numbers(object, "extrinsic", 16, e, where);
    p.extrinsic = Eigen::Map<const Eigen::Matrix4d>(e);  // Eigen's default storage is column-major too
    return p;
}

json intrinsic_to(const PinholeCameraIntrinsic& in) {
    require_finite_intrinsic(in, "intrinsic");
    return json{{"width", in.width},
                {"height", in.height},
                {"intrinsic_matrix", {in.fx, 0.0, 0.0, 0.0, in.fy, 0.0, in.cx, in.cy, 1.0}}};
}

json parameters_to(const PinholeCameraParameters& p) {
    if (!p.extrinsic.allFinite()) throw InvalidArgument("extrinsic has a NaN or infinite entry");
    json extrinsic = json::array();
    for (int k = 0; k < 16; ++k) extrinsic.push_back(p.extrinsic.data()[k]);
    return json{{"class_name", "PinholeCameraParameters"},
                {"extrinsic", std::move(extrinsic)},
                {"intrinsic", intrinsic_to(p.intrinsic)},
                {"version_major", 1},
                {"version_minor", 0}};
}

std::string dump(const json& j) { return j.dump(1, '\t') + "\n"; }

}  // namespace

PinholeCameraIntrinsic parse_intrinsic_json(std::string_view text, const std::string& name) {
    return intrinsic_from(parse_text(text, name), Where{name, ""});
}

PinholeCameraParameters parse_parameters_json(std::string_view text, const std::string& name) {
    return parameters_from(parse_text(text, name), Where{name, ""});
}

PinholeCameraTrajectory parse_trajectory_json(std::string_view text, const std::string& name) {
    const json root = parse_text(text, name);
    const Where where{name, ""};
    check_class(root, "PinholeCameraTrajectory", where);
    const json& list = member(root, "parameters", where);
    if (!list.is_array()) where.at("parameters").fail("expected an array");
    PinholeCameraTrajectory t;
    t.parameters.reserve(list.size());
    for (size_t k = 0; k < list.size(); ++k)
        t.parameters.push_back(parameters_from(list[k], where.at("parameters[" + std::to_string(k) + "]")));
    return t;
}

std::string format_intrinsic_json(const PinholeCameraIntrinsic& intrinsic) { return dump(intrinsic_to(intrinsic)); }

std::string format_parameters_json(const PinholeCameraParameters& parameters) {
    return dump(parameters_to(parameters));
}

std::string format_trajectory_json(const PinholeCameraTrajectory& trajectory) {
    json list = json::array();
    for (const auto& p : trajectory.parameters) list.push_back(parameters_to(p));
    return dump(json{{"class_name", "PinholeCameraTrajectory"},
                     {"parameters", std::move(list)},
                     {"version_major", 1},
                     {"version_minor", 0}});
}

}  // namespace o3d::camera
