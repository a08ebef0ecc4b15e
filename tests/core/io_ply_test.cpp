// SPDX-License-Identifier: MIT
// PLY specifics: encodings, property types, skipped properties and elements.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "io_test_util.h"

namespace {

using o3d::test::read_text;

template <typename T>
void put(std::string& s, T v, bool big_endian) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof v);
    if (big_endian)
        for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    s.append(b, sizeof b);
}

// A face element before the vertices (with lists), a mixed-type vertex record with an unused
// list, float colours, and a trailing element: everything but x y z nx ny nz red green blue must
// be stepped over correctly in both byte orders.
std::string tricky_binary(bool big) {
    std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\ncomment skipped\nobj_info skipped too\n"
                    "element face 2\nproperty list uchar int vertex_indices\nproperty short flags\n"
                    "element vertex 2\nproperty double x\nproperty uint16 tag\nproperty float y\n"
                    "property list int float weights\nproperty float z\nproperty int8 nx\nproperty int8 ny\n"
                    "property int8 nz\nproperty float red\nproperty float green\nproperty float blue\n"
                    "element camera 1\nproperty float k\nend_header\n";
    // faces: 3 indices then 0 indices
    put<uint8_t>(s, 3, big), put<int32_t>(s, 0, big), put<int32_t>(s, 1, big), put<int32_t>(s, 2, big),
        put<int16_t>(s, -1, big);
    put<uint8_t>(s, 0, big), put<int16_t>(s, 7, big);
    for (int v = 0; v < 2; ++v) {
        put<double>(s, 1.5 + v, big);
        put<uint16_t>(s, 0xBEEF, big);
        put<float>(s, -2.25f, big);
        put<int32_t>(s, v ? 2 : 0, big);
        for (int w = 0; w < (v ? 2 : 0); ++w) put<float>(s, 9.f, big);
        put<float>(s, 1e6f, big);
        put<int8_t>(s, 0, big), put<int8_t>(s, -1, big), put<int8_t>(s, 1, big);
        put<float>(s, 0.25f, big), put<float>(s, 0.5f, big), put<float>(s, 1.0f, big);
    }
    put<float>(s, 3.f, big);
    return s;
}

TEST(ioPlyRead, SkipsEverythingItDoesNotKeepInBothByteOrders) {
    for (bool big : {false, true}) {
        const auto pc = read_text(tricky_binary(big), "ply");
        ASSERT_EQ(pc.size(), 2u) << big;
        EXPECT_EQ(pc.points[0], Eigen::Vector3d(1.5, -2.25, 1e6)) << big;
        EXPECT_EQ(pc.points[1], Eigen::Vector3d(2.5, -2.25, 1e6)) << big;
        ASSERT_TRUE(pc.has_normals());
        EXPECT_EQ(pc.normals[1], Eigen::Vector3d(0, -1, 1));
        ASSERT_TRUE(pc.has_colors());
        EXPECT_EQ(pc.colors[0], Eigen::Vector3d(0.25, 0.5, 1.0));  // float colours are taken as they are
    }
}

TEST(ioPlyRead, TruncatedTrailingElementIsAnError) {
    std::string s = tricky_binary(false);
    s.pop_back();
    EXPECT_NE(o3d::test::parse_error_of(o3d::test::bytes_of(s), "ply").find("camera"), std::string::npos);
}

TEST(ioPlyRead, AsciiWithFacesAndIntegerColours) {
    const std::string text =
        "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
        "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\nproperty ushort quality\r\n"
        "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
        "0 0 0 255 0 51 7\r\n1 +2.5 -3e2 0 255 0 7\r\n.5 nan inf 1 2 3 7\r\n3 0 1 2\r\n";
    const auto pc = read_text(text, "ply");
    ASSERT_EQ(pc.size(), 3u);
    EXPECT_EQ(pc.points[1], Eigen::Vector3d(1, 2.5, -300));
    EXPECT_EQ(pc.colors[0], Eigen::Vector3d(1, 0, 0.2));
    EXPECT_TRUE(std::isnan(pc.points[2].y()));
    EXPECT_TRUE(std::isinf(pc.points[2].z()));
    EXPECT_FALSE(pc.has_normals());
}

TEST(ioPlyRead, SixteenBitColoursScaleByTheirRange) {
    std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                    "property float z\nproperty ushort red\nproperty ushort green\nproperty ushort blue\nend_header\n";
    put<float>(s, 1, false), put<float>(s, 2, false), put<float>(s, 3, false);
    put<uint16_t>(s, 65535, false), put<uint16_t>(s, 0, false), put<uint16_t>(s, 13107, false);
    const auto pc = read_text(s, "ply");
    ASSERT_TRUE(pc.has_colors());
    EXPECT_EQ(pc.colors[0], Eigen::Vector3d(1, 0, 0.2));
}

TEST(ioPlyRead, PartialNormalsAreIgnored) {
    const auto pc = read_text(
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nend_header\n1 2 3 4 5\n",
        "ply");
    EXPECT_EQ(pc.size(), 1u);
    EXPECT_FALSE(pc.has_normals());
}

TEST(ioPlyRead, ZeroVerticesIsAnEmptyCloud) {
    const auto pc = read_text("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n",
                              "ply");
    EXPECT_EQ(pc.size(), 0u);
}

}  // namespace
