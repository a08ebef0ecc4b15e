// SPDX-License-Identifier: MIT
// Camera models: presets, Open3D's JSON layouts and the .log trajectory format.
// Reference extrinsics: Open3D 0.20.0 (pip wheel), printed by tools/reference/record_rgbd.py (section "camera").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "o3d/camera/camera_io.h"
#include "o3d/camera/camera_json_io.h"
#include "o3d/camera/intrinsic_presets.h"
#include "o3d/camera/trajectory_log_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace {

using namespace o3d::camera;

using RowMajor4 = double[4][4];

void expect_matrix_near(const Eigen::Matrix4d& m, const RowMajor4& ref, double tol) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(m(r, c), ref[r][c], tol) << "(" << r << "," << c << ")";
}

void expect_intrinsic_eq(const PinholeCameraIntrinsic& a, const PinholeCameraIntrinsic& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.fx, b.fx);
    EXPECT_EQ(a.fy, b.fy);
    EXPECT_EQ(a.cx, b.cx);
    EXPECT_EQ(a.cy, b.cy);
}

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "o3d_camera_test_" + name; }

std::string parse_error_message(const std::function<void()>& f) {
    try {
        f();
    } catch (const o3d::ParseError& e) {
        return e.what();
    }
    return "";
}

void expect_parse_error(const std::function<void()>& f, const std::string& reason) {
    const std::string msg = parse_error_message(f);
    ASSERT_FALSE(msg.empty()) << "accepted; expected a ParseError containing: " << reason;
    EXPECT_EQ(msg.rfind("<memory>: ", 0), 0u) << msg;
    EXPECT_NE(msg.find(reason), std::string::npos) << "message: " << msg << "\nexpected: " << reason;
}

TEST(cameraPresets, MatchOpen3D) {
    const PinholeCameraIntrinsic ps = intrinsic_preset(IntrinsicPreset::PrimeSenseDefault);
    expect_intrinsic_eq(ps, {640, 480, 525.0, 525.0, 319.5, 239.5});
    expect_intrinsic_eq(intrinsic_preset(IntrinsicPreset::Kinect2DepthCameraDefault),
                        {512, 424, 365.456, 365.456, 254.878, 205.395});
    expect_intrinsic_eq(intrinsic_preset(IntrinsicPreset::Kinect2ColorCameraDefault),
                        {1920, 1080, 1059.9718, 1059.9718, 975.7193, 545.9533});
    EXPECT_THROW(intrinsic_preset(static_cast<IntrinsicPreset>(7)), o3d::InvalidArgument);
}

TEST(cameraJson, ReadsOpen3DIntrinsic) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/camera_primesense.json");
    expect_intrinsic_eq(read_pinhole_camera_intrinsic(path), intrinsic_preset(IntrinsicPreset::PrimeSenseDefault));
}

TEST(cameraJson, ReadsOpen3DTrajectory) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/camera_trajectory.json");
    const PinholeCameraTrajectory t = read_pinhole_camera_trajectory(path);
    ASSERT_EQ(t.parameters.size(), 31u);
    expect_intrinsic_eq(t.parameters[30].intrinsic, {1920, 1080, 935.30743608719376, 935.30743608719376, 959.5, 539.5});
    // Open3D: parameters[1].extrinsic and parameters[30].extrinsic (row-major).
    const RowMajor4 e1 = {{0.9992879577710159, -0.006715136819757545, 0.0371279462308972, -2.3078035383191513},
                          {0.016150876271446853, 0.9654520063147016, -0.260079935209508, -1.2035828634030123},
                          {-0.03409877782995854, 0.2604943961785155, 0.9648730190600698, 1.125458179216736},
                          {0.0, 0.0, 0.0, 1.0}};
    const RowMajor4 e30 = {{0.9635784037403037, 0.011825572766665078, -0.2671643982158344, -1.7817411939858416},
                           {-0.045318516171068614, 0.9917933785596154, -0.11954968146070559, -1.3270427866885102},
                           {0.2635581376799836, 0.12730298533044657, 0.9562065979633351, -0.5273274482247282},
                           {0.0, 0.0, 0.0, 1.0}};
    expect_matrix_near(t.parameters[1].extrinsic, e1, 0.0);  // parsed text: bit-identical
    expect_matrix_near(t.parameters[30].extrinsic, e30, 0.0);
}

TEST(cameraJson, OldSingleIntrinsicLayoutIsRejected) {
    // depth_syn_camera.json predates the "parameters" list; Open3D also fails on it (empty trajectory).
    O3D_TEST_DATA_OR_SKIP(path, "open3d/depth_syn_camera.json");
    try {
        read_pinhole_camera_trajectory(path);
        FAIL() << "accepted";
    } catch (const o3d::ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("missing \"parameters\""), std::string::npos) << e.what();
    }
}

TEST(cameraLog, ReadsOpen3DTrajectoryLog) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/RGBD/trajectory.log");
    const PinholeCameraTrajectory t = read_pinhole_camera_trajectory(path);
    ASSERT_EQ(t.parameters.size(), 5u);
    for (const auto& p : t.parameters)
        expect_intrinsic_eq(p.intrinsic, intrinsic_preset(IntrinsicPreset::PrimeSenseDefault));
    // Open3D stores extrinsic = inverse(pose).
    const RowMajor4 e0 = {{-0.27395921869243245, 8.67361737988404e-19, -0.9617413095492114, 1.9600374316214595},
                          {0.021819345900466688, -0.9997426093226986, -0.006215404179813819, 0.5928583404313622},
                          {-0.9614937663021577, -0.02268733357278152, 0.2738887041435803, -0.8680394419320993},
                          {0.0, 0.0, 0.0, 1.0}};
    const RowMajor4 e4 = {{-0.2589186421085548, 0.0, -0.9658991338481787, 1.9684600200041038},
                          {0.07016430847656363, -0.997358120495347, -0.018808224211631922, 0.7304114882103011},
                          {-0.9633473447229031, -0.07264144465791822, 0.2582346102545956, -0.795113314908377},
                          {0.0, 0.0, 0.0, 1.0}};
    expect_matrix_near(t.parameters[0].extrinsic, e0, 1e-14);
    expect_matrix_near(t.parameters[4].extrinsic, e4, 1e-14);
}

TEST(cameraLog, ReadsOpen3DOdometryLog) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/RGBD/odometry.log");
    const PinholeCameraTrajectory t = read_pinhole_camera_trajectory(path, "log");
    ASSERT_EQ(t.parameters.size(), 5u);
    const RowMajor4 e1 = {{0.9999878111951102, -8.841786101516963e-05, -0.004917403680443615, -2.000898432336347},
                          {3.0866835565659854e-05, 0.9999310471066116, -0.011702492807552398, -1.9804818345671593},
                          {0.004918099644898596, 0.011702106170270447, 0.9999198654164094, 0.26749205828471156},
                          {0.0, 0.0, 0.0, 1.0}};
    const RowMajor4 e4 = {{0.9998526851887904, -0.0004345553939697508, -0.01714943976668741, -2.005355043722487},
                          {-0.000399721696495155, 0.9988171235665163, -0.04861394859059105, -1.9166640697732569},
                          {0.017150334348440825, 0.04861365077921932, 0.9986698093625812, 0.17808012507595006},
                          {0.0, 0.0, 0.0, 1.0}};
    expect_matrix_near(t.parameters[1].extrinsic, e1, 1e-14);
    expect_matrix_near(t.parameters[4].extrinsic, e4, 1e-14);
    // The first pose is a pure translation by (2, 2, -0.3): its inverse translates back.
    EXPECT_DOUBLE_EQ(t.parameters[0].extrinsic(0, 3), -2.0);
    EXPECT_DOUBLE_EQ(t.parameters[0].extrinsic(2, 3), 0.3);
}

PinholeCameraTrajectory sample_trajectory() {
    PinholeCameraTrajectory t;
    for (int i = 0; i < 3; ++i) {
        PinholeCameraParameters p;
        p.intrinsic = {320 + i, 240, 500.25 + i, 501.125, 159.5, 119.5 + 0.1 * i};
        const double a = 0.3 * (i + 1);
        p.extrinsic.block<3, 3>(0, 0) << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
        p.extrinsic.block<3, 1>(0, 3) << 0.1 * i, -1.0 / 3.0, 2.0 + i;
        t.parameters.push_back(p);
    }
    return t;
}

TEST(cameraJson, RoundTripsExactly) {
    const PinholeCameraTrajectory t = sample_trajectory();
    const std::string tp = temp_path("traj.json");
    write_pinhole_camera_trajectory(tp, t);
    const PinholeCameraTrajectory back = read_pinhole_camera_trajectory(tp, "json");
    ASSERT_EQ(back.parameters.size(), t.parameters.size());
    for (size_t i = 0; i < t.parameters.size(); ++i) {
        expect_intrinsic_eq(back.parameters[i].intrinsic, t.parameters[i].intrinsic);
        EXPECT_TRUE(back.parameters[i].extrinsic == t.parameters[i].extrinsic) << i;
    }

    const std::string ip = temp_path("intrinsic.json");
    write_pinhole_camera_intrinsic(ip, t.parameters[2].intrinsic);
    expect_intrinsic_eq(read_pinhole_camera_intrinsic(ip), t.parameters[2].intrinsic);

    const std::string pp = temp_path("params.json");
    write_pinhole_camera_parameters(pp, t.parameters[1]);
    const PinholeCameraParameters p = read_pinhole_camera_parameters(pp);
    expect_intrinsic_eq(p.intrinsic, t.parameters[1].intrinsic);
    EXPECT_TRUE(p.extrinsic == t.parameters[1].extrinsic);
    std::remove(tp.c_str());
    std::remove(ip.c_str());
    std::remove(pp.c_str());
}

TEST(cameraJson, WritesOpen3DLayout) {
    PinholeCameraParameters p;
    p.intrinsic = {4, 3, 10, 11, 1.5, 1};
    p.extrinsic(0, 3) = 7;  // column-major: the translation is elements 12..14
    const std::string text = format_parameters_json(p);
    const PinholeCameraParameters back = parse_parameters_json(text, "<memory>");
    EXPECT_EQ(back.extrinsic(0, 3), 7.0);
    for (const char* field : {"\"class_name\"", "\"PinholeCameraParameters\"", "\"version_major\"",
                              "\"version_minor\"", "\"intrinsic_matrix\"", "\"extrinsic\""})
        EXPECT_NE(text.find(field), std::string::npos) << field;
    // intrinsic_matrix is column-major: fx, 0, 0, 0, fy, 0, cx, cy, 1.
    const PinholeCameraIntrinsic in =
        parse_intrinsic_json(R"({"width": 4, "height": 3, "intrinsic_matrix": [10,0,0, 0,11,0, 1.5,1,1]})",
                             "<memory>");
    expect_intrinsic_eq(in, p.intrinsic);
    const std::string ext = R"({"class_name":"PinholeCameraParameters","intrinsic":{"width":4,"height":3,)"
                            R"("intrinsic_matrix":[10,0,0,0,11,0,1.5,1,1]},)"
                            R"("extrinsic":[1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1]})";
    const PinholeCameraParameters q = parse_parameters_json(ext, "<memory>");
    EXPECT_EQ(q.extrinsic(0, 3), 5.0);
    EXPECT_EQ(q.extrinsic(1, 3), 6.0);
    EXPECT_EQ(q.extrinsic(2, 3), 7.0);
    EXPECT_EQ(q.extrinsic(3, 0), 0.0);
}

TEST(cameraJson, MalformedGivesParseError) {
    const auto intr = [](const std::string& s) { return [s] { parse_intrinsic_json(s, "<memory>"); }; };
    const auto par = [](const std::string& s) { return [s] { parse_parameters_json(s, "<memory>"); }; };
    const auto traj = [](const std::string& s) { return [s] { parse_trajectory_json(s, "<memory>"); }; };
    const std::string m9 = R"("intrinsic_matrix": [1,0,0,0,1,0,0,0,1])";
    expect_parse_error(intr(""), "invalid JSON");
    expect_parse_error(intr("{\"width\": 3,"), "invalid JSON");
    expect_parse_error(intr("[1, 2]"), "expected a JSON object");
    expect_parse_error(intr("{\"height\": 3, " + m9 + "}"), "missing \"width\"");
    expect_parse_error(intr("{\"width\": 3.5, \"height\": 3, " + m9 + "}"), "width: expected an integer");
    expect_parse_error(intr("{\"width\": 99999999999, \"height\": 3, " + m9 + "}"), "out of range");
    expect_parse_error(intr(R"({"width": 3, "height": 3, "intrinsic_matrix": [1, 2, 3]})"), "array of 9 numbers");
    expect_parse_error(intr(R"({"width": 3, "height": 3, "intrinsic_matrix": [1,0,0,0,1,0,0,"x",1]})"),
                       "element 7 is not a number");
    expect_parse_error(intr(R"({"width": 3, "height": 3, "intrinsic_matrix": [1e999,0,0,0,1,0,0,0,1]})"), "");

    const std::string good_intr = "{\"width\": 3, \"height\": 3, " + m9 + "}";
    const std::string e16 = R"("extrinsic": [1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1])";
    expect_parse_error(par("{\"intrinsic\": " + good_intr + ", " + e16 + "}"), "missing \"class_name\"");
    expect_parse_error(par("{\"class_name\": \"Foo\", \"intrinsic\": " + good_intr + ", " + e16 + "}"),
                       "is not \"PinholeCameraParameters\"");
    expect_parse_error(par("{\"class_name\": \"PinholeCameraParameters\", \"version_minor\": 1, \"intrinsic\": " +
                           good_intr + ", " + e16 + "}"),
                       "unsupported version 1.1");
    expect_parse_error(par(R"({"class_name": "PinholeCameraParameters", "intrinsic": )" + good_intr +
                           R"(, "extrinsic": [1,0,0]})"),
                       "array of 16 numbers");
    expect_parse_error(par(R"({"class_name": "PinholeCameraParameters", "intrinsic": {"width": 1}, )" + e16 + "}"),
                       "missing \"height\"");

    expect_parse_error(traj(R"({"class_name": "PinholeCameraTrajectory"})"), "missing \"parameters\"");
    expect_parse_error(traj(R"({"class_name": "PinholeCameraTrajectory", "parameters": 3})"),
                       "parameters: expected an array");
    expect_parse_error(traj(R"({"class_name": "PinholeCameraTrajectory", "parameters": [{}]})"),
                       "parameters[0]: missing \"class_name\"");
    // An empty list is a valid (empty) trajectory: what writing an empty trajectory produces.
    EXPECT_TRUE(parse_trajectory_json(format_trajectory_json({}), "<memory>").parameters.empty());
}

TEST(cameraJson, NonFiniteValuesAreNotWritten) {
    PinholeCameraIntrinsic in{640, 480, NAN, 525, 319.5, 239.5};
    EXPECT_THROW(format_intrinsic_json(in), o3d::InvalidArgument);
    PinholeCameraParameters p;
    p.extrinsic(1, 2) = INFINITY;
    EXPECT_THROW(format_parameters_json(p), o3d::InvalidArgument);
}

TEST(cameraLog, RoundTrips) {
    const PinholeCameraTrajectory t = sample_trajectory();
    const std::string text = format_trajectory_log(t);
    EXPECT_EQ(text.rfind("0 0 1\n", 0), 0u) << text.substr(0, 40);
    const PinholeCameraTrajectory back = parse_trajectory_log(text, "<memory>");
    ASSERT_EQ(back.parameters.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        // .log holds no intrinsic: the PrimeSense default comes back.
        expect_intrinsic_eq(back.parameters[i].intrinsic, intrinsic_preset(IntrinsicPreset::PrimeSenseDefault));
        EXPECT_LT((back.parameters[i].extrinsic - t.parameters[i].extrinsic).cwiseAbs().maxCoeff(), 1e-14) << i;
    }
}

TEST(cameraLog, MalformedGivesParseError) {
    const auto log = [](const std::string& s) { return [s] { parse_trajectory_log(s, "<memory>"); }; };
    const std::string id = "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
    expect_parse_error(log("0 0\n" + id), "line 1: expected a frame line of three integers");
    expect_parse_error(log("0 0 x\n" + id), "three integers");
    expect_parse_error(log("0 0 1\n1 0 0 0\n0 1 0 0\n"), "line 3: the file ends inside a pose (row 3)");
    expect_parse_error(log("0 0 1\n1 0 0 0\n0 1 zero 0\n0 0 1 0\n0 0 0 1\n"), "line 3: expected four finite numbers");
    expect_parse_error(log("0 0 1\n1 0 0 0\n0 1 0\n0 0 1 0\n0 0 0 1\n"), "pose row 2");
    expect_parse_error(log("0 0 1\n1 0 0 0 5\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"), "more than four numbers");
    expect_parse_error(log("0 0 1\n1 0 0 nan\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"), "finite");
    expect_parse_error(log("0 0 1\n0 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"), "line 5: the pose is not invertible");
    // Blank lines between frames and CRLF line ends are fine.
    EXPECT_EQ(parse_trajectory_log("\n0 0 1\r\n" + id + "\n\n1 1 2\n" + id, "<memory>").parameters.size(), 2u);
    EXPECT_TRUE(parse_trajectory_log("", "<memory>").parameters.empty());
}

TEST(cameraIo, FormatsAndFileErrors) {
    const std::string dir = ::testing::TempDir();
    EXPECT_THROW(read_pinhole_camera_trajectory(dir + "o3d_missing_trajectory.json"), o3d::IoError);
    EXPECT_THROW(read_pinhole_camera_intrinsic(dir + "o3d_missing_intrinsic.json"), o3d::IoError);
    EXPECT_THROW(read_pinhole_camera_trajectory(dir + "o3d_trajectory.txt"), o3d::Unsupported);
    EXPECT_THROW(read_pinhole_camera_trajectory(dir + "o3d_trajectory.json", "yaml"), o3d::Unsupported);
    EXPECT_THROW(write_pinhole_camera_trajectory(dir + "no_such_dir/x/t.log", sample_trajectory()), o3d::IoError);
    // Explicit format beats the extension; upper-case extensions work.
    const std::string p = temp_path("TRAJ.LOG");
    write_pinhole_camera_trajectory(p, sample_trajectory());
    EXPECT_EQ(read_pinhole_camera_trajectory(p).parameters.size(), 3u);
    EXPECT_THROW(read_pinhole_camera_trajectory(p, "json"), o3d::ParseError);
    std::remove(p.c_str());
    // A singular extrinsic has no pose to write.
    PinholeCameraTrajectory bad;
    bad.parameters.emplace_back();
    bad.parameters[0].extrinsic.setZero();
    EXPECT_THROW(format_trajectory_log(bad), o3d::InvalidArgument);
}

}  // namespace
