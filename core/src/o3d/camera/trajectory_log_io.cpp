// SPDX-License-Identifier: MIT
#include "o3d/camera/trajectory_log_io.h"

#include <charconv>
#include <cmath>

#include "o3d/camera/camera_checks.h"
#include "o3d/camera/intrinsic_presets.h"
#include "o3d/io/byte_reader.h"
#include "o3d/utility/error.h"

namespace o3d::camera {
namespace {

using io::detail::TextCursor;

class LogLines {
public:
    LogLines(std::string_view text, const std::string& name) : cursor_(text), name_(name) {}

    /// @brief The next non-blank line; false at the end of the text.
    bool next(std::string_view& line) {
        while (!cursor_.at_end()) {
            line = cursor_.line();
            ++line_no_;
            if (!TextCursor(line).only_whitespace_left()) return true;
        }
        return false;
    }
    [[noreturn]] void fail(const std::string& reason) const {
        throw ParseError(name_ + ": line " + std::to_string(line_no_) + ": " + reason);
    }

private:
    TextCursor cursor_;
    const std::string& name_;
    size_t line_no_ = 0;
};

void parse_frame_header(std::string_view line, const LogLines& lines) {
    TextCursor c(line);
    for (int k = 0; k < 3; ++k) {
        int64_t id = 0;
        if (!io::detail::parse_int64(c.token(), id)) lines.fail("expected a frame line of three integers");
    }
    if (!c.only_whitespace_left()) lines.fail("expected a frame line of three integers");
}

void parse_pose_row(std::string_view line, Eigen::Matrix4d& pose, int row, const LogLines& lines) {
    TextCursor c(line);
    std::string_view tok;
    for (int col = 0; col < 4; ++col) {
        double v = 0;
        if (!c.number(v, tok) || !std::isfinite(v)) lines.fail("expected four finite numbers in pose row " +
                                                               std::to_string(row + 1));
        pose(row, col) = v;
    }
    if (!c.only_whitespace_left()) lines.fail("more than four numbers in pose row " + std::to_string(row + 1));
}

void put_number(std::string& out, double v) {
    if (v == 0.0) v = 0.0;  // inverting an exact pose yields -0 entries; write them as 0
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    out.append(buf, end);
}

}  // namespace

PinholeCameraTrajectory parse_trajectory_log(std::string_view text, const std::string& name) {
    const PinholeCameraIntrinsic intrinsic = intrinsic_preset(IntrinsicPreset::PrimeSenseDefault);
    PinholeCameraTrajectory trajectory;
    LogLines lines(text, name);
    std::string_view line;
    while (lines.next(line)) {
        parse_frame_header(line, lines);
        Eigen::Matrix4d pose;
        for (int row = 0; row < 4; ++row) {
            if (!lines.next(line)) lines.fail("the file ends inside a pose (row " + std::to_string(row + 1) + ")");
            parse_pose_row(line, pose, row, lines);
        }
        PinholeCameraParameters p;
        p.intrinsic = intrinsic;
        try {
            p.extrinsic = checked_inverse(pose, "pose");
        } catch (const InvalidArgument&) {
            lines.fail("the pose is not invertible");
        }
        trajectory.parameters.push_back(p);
    }
    return trajectory;
}

std::string format_trajectory_log(const PinholeCameraTrajectory& trajectory) {
    std::string out;
    out.reserve(trajectory.parameters.size() * 200);
    for (size_t i = 0; i < trajectory.parameters.size(); ++i) {
        const Eigen::Matrix4d pose = checked_inverse(trajectory.parameters[i].extrinsic, "extrinsic");
        out += std::to_string(i) + " " + std::to_string(i) + " " + std::to_string(i + 1) + "\n";
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) {
                put_number(out, pose(r, c));
                out += c == 3 ? '\n' : ' ';
            }
        }
    }
    return out;
}

}  // namespace o3d::camera
