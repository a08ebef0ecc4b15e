// SPDX-License-Identifier: MIT
#include "o3d/camera/camera_io.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

#include "o3d/camera/camera_json_io.h"
#include "o3d/camera/trajectory_log_io.h"
#include "o3d/io/file_bytes.h"
#include "o3d/utility/error.h"

namespace o3d::camera {
namespace {

std::string read_text(const std::string& path) {
    const io::detail::FileBytes bytes(path);
    return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

void write_text(const std::string& path, const std::string& text) {
    io::detail::write_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// @brief "json" or "log" from the explicit format or, for "auto"/"", the path's extension.
std::string trajectory_format(const std::string& path, const std::string& format) {
    std::string f = lower(format);
    if (f.empty() || f == "auto") {
        const size_t dot = path.find_last_of('.');
        const size_t slash = path.find_last_of("/\\");
        f = (dot == std::string::npos || (slash != std::string::npos && dot < slash)) ? "" : lower(path.substr(dot + 1));
        if (f != "json" && f != "log")
            throw Unsupported("cannot tell the trajectory format of '" + path + "' (extension .json or .log expected)");
    }
    if (f != "json" && f != "log") throw Unsupported("unknown trajectory format '" + format + "' (json, log)");
    return f;
}

}  // namespace

PinholeCameraIntrinsic read_pinhole_camera_intrinsic(const std::string& path) {
    return parse_intrinsic_json(read_text(path), path);
}

void write_pinhole_camera_intrinsic(const std::string& path, const PinholeCameraIntrinsic& intrinsic) {
    write_text(path, format_intrinsic_json(intrinsic));
}

PinholeCameraParameters read_pinhole_camera_parameters(const std::string& path) {
    return parse_parameters_json(read_text(path), path);
}

void write_pinhole_camera_parameters(const std::string& path, const PinholeCameraParameters& parameters) {
    write_text(path, format_parameters_json(parameters));
}

PinholeCameraTrajectory read_pinhole_camera_trajectory(const std::string& path, const std::string& format) {
    const std::string f = trajectory_format(path, format);
    const std::string text = read_text(path);
    return f == "json" ? parse_trajectory_json(text, path) : parse_trajectory_log(text, path);
}

void write_pinhole_camera_trajectory(const std::string& path, const PinholeCameraTrajectory& trajectory,
                                     const std::string& format) {
    const std::string f = trajectory_format(path, format);
    write_text(path, f == "json" ? format_trajectory_json(trajectory) : format_trajectory_log(trajectory));
}

}  // namespace o3d::camera
