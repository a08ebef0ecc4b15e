// SPDX-License-Identifier: MIT
// PCD specifics: field layouts, packed colours, organized clouds, the three DATA encodings.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "io_test_util.h"

namespace {

using o3d::test::read_text;

template <typename T>
void put(std::string& s, T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Fields of every size and type around the kept ones, an array field (COUNT 3), rgba as U4 and
// the coordinates as doubles.
std::string header(const char* data, int points) {
    return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
           "FIELDS pad x y z intensity normal_x normal_y normal_z rgba label\n"
           "SIZE 1 8 8 8 2 4 4 4 4 8\nTYPE U F F F I F F F U I\nCOUNT 1 1 1 1 3 1 1 1 1 1\n"
           "WIDTH " + std::to_string(points) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points) +
           "\nDATA " + data + "\n";
}

void put_point(std::string& s, int i) {
    put<uint8_t>(s, 0xAA);
    put<double>(s, 0.1 * i), put<double>(s, -0.2), put<double>(s, 1e-300);
    put<int16_t>(s, 1), put<int16_t>(s, 2), put<int16_t>(s, 3);
    put<float>(s, 0.f), put<float>(s, 1.f), put<float>(s, 0.f);
    put<uint32_t>(s, 0xFF336699u);  // alpha ff, r 0x33, g 0x66, b 0x99
    put<int64_t>(s, -5);
}

void expect_layout_cloud(const o3d::geometry::PointCloud& pc, int n) {
    ASSERT_EQ(pc.size(), static_cast<size_t>(n));
    EXPECT_EQ(pc.points[1], Eigen::Vector3d(0.1, -0.2, 1e-300));
    ASSERT_TRUE(pc.has_normals());
    EXPECT_EQ(pc.normals[0], Eigen::Vector3d(0, 1, 0));
    ASSERT_TRUE(pc.has_colors());
    EXPECT_EQ(pc.colors[1], Eigen::Vector3d(0x33 / 255.0, 0x66 / 255.0, 0x99 / 255.0));
}

TEST(ioPcdRead, BinarySkipsFieldsOfEverySize) {
    std::string s = header("binary", 3);
    for (int i = 0; i < 3; ++i) put_point(s, i);
    expect_layout_cloud(read_text(s, "pcd"), 3);
}

TEST(ioPcdRead, AsciiSkipsFieldsOfEveryCount) {
    std::string s = header("ascii", 2);
    const std::string rgba = std::to_string(0xFF336699u);
    s += "170 0 -0.2 1e-300 1 2 3 0 1 0 " + rgba + " -5\n";
    s += "170 0.1 -0.2 1e-300 1 2 3 0 1 0 " + rgba + " -5\n";
    expect_layout_cloud(read_text(s, "pcd"), 2);
}

TEST(ioPcdRead, PackedFloatRgbInAscii) {
    uint32_t bits = 0x00ff8000u;
    float f;
    std::memcpy(&f, &bits, 4);
    char num[64];
    std::snprintf(num, sizeof num, "%.9g", f);  // how PCL prints the float-packed colour
    const std::string s = "VERSION .7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\n"
                          "DATA ascii\n1 2 3 " + std::string(num) + "\n";
    const auto pc = read_text(s, "pcd");
    ASSERT_TRUE(pc.has_colors());
    EXPECT_EQ(pc.colors[0], Eigen::Vector3d(1, 128 / 255.0, 0));
}

TEST(ioPcdRead, OrganizedCloudKeepsNaNsUnlessAsked) {
    // 2 x 2 organized cloud with two invalid pixels, as depth sensors write it.
    const std::string s = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\nPOINTS 4\n"
                          "DATA ascii\n1 1 1\nnan nan nan\n2 2 2\n3 inf 3\n";
    EXPECT_EQ(read_text(s, "pcd").size(), 4u);
    o3d::io::ReadOptions nan;
    nan.remove_nan_points = true;
    const auto no_nan = read_text(s, "pcd", nan);
    ASSERT_EQ(no_nan.size(), 3u);
    EXPECT_EQ(no_nan.points[1], Eigen::Vector3d(2, 2, 2));
    o3d::io::ReadOptions both = nan;
    both.remove_infinite_points = true;
    EXPECT_EQ(read_text(s, "pcd", both).size(), 2u);
    o3d::io::ReadOptions inf;
    inf.remove_infinite_points = true;
    EXPECT_EQ(read_text(s, "pcd", inf).size(), 3u);
}

TEST(ioPcdRead, NanRemovalKeepsAttributesAligned) {
    o3d::geometry::PointCloud in = o3d::test::make_cloud(6, true, true);
    in.points[0].x() = std::numeric_limits<double>::quiet_NaN();
    in.points[4].z() = std::numeric_limits<double>::quiet_NaN();
    const auto bytes = o3d::io::write_point_cloud_to_memory(in, "ply");
    o3d::io::ReadOptions o;
    o.remove_nan_points = true;
    const auto pc = o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), "ply", o);
    ASSERT_EQ(pc.size(), 4u);
    EXPECT_EQ(pc.points[0], in.points[1]);
    EXPECT_EQ(pc.normals[3], in.normals[5]);
    EXPECT_EQ(pc.colors[2], in.colors[3]);
}

TEST(ioPcdRead, HeaderWithoutPointsUsesWidthTimesHeight) {
    std::string s = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 2\nDATA binary\n";
    for (int i = 0; i < 18; ++i) put<float>(s, float(i));
    const auto pc = read_text(s, "pcd");
    ASSERT_EQ(pc.size(), 6u);
    EXPECT_EQ(pc.points[5], Eigen::Vector3d(15, 16, 17));
}

TEST(ioPcdRead, RgbOfOtherSizesIsNotAColour) {
    std::string s = "FIELDS x y z rgb\nSIZE 4 4 4 8\nTYPE F F F F\nPOINTS 1\nDATA binary\n";
    put<float>(s, 1), put<float>(s, 2), put<float>(s, 3), put<double>(s, 4);
    const auto pc = read_text(s, "pcd");
    EXPECT_EQ(pc.size(), 1u);
    EXPECT_FALSE(pc.has_colors());
}

}  // namespace
