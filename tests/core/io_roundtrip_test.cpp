// SPDX-License-Identifier: MIT
// Write then read back every format with every option and attribute combination.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>

#include "io_test_util.h"

namespace {

using o3d::geometry::PointCloud;
using o3d::test::expect_near;
using o3d::test::make_cloud;

struct Case {
    std::string format;
    bool ascii;
    bool compressed;
    bool normals;
    bool colors;
};

std::string name_of(const Case& c) {
    return c.format + (c.ascii ? "_ascii" : "") + (c.compressed ? "_compressed" : "") + (c.normals ? "_normals" : "") +
           (c.colors ? "_colors" : "");
}

std::string case_name(const testing::TestParamInfo<Case>& info) { return name_of(info.param); }
// Keeps gtest from printing the struct as raw bytes in test names.
void PrintTo(const Case& c, std::ostream* os) { *os << name_of(c); }

std::vector<Case> all_cases() {
    std::vector<Case> out;
    for (bool n : {false, true})
        for (bool c : {false, true}) {
            for (bool a : {false, true}) out.push_back({"ply", a, false, n, c});
            out.push_back({"pcd", false, false, n, c});
            out.push_back({"pcd", true, false, n, c});
            out.push_back({"pcd", false, true, n, c});
        }
    out.push_back({"xyz", false, false, false, false});
    out.push_back({"xyzn", false, false, true, false});
    out.push_back({"xyzrgb", false, false, false, true});
    out.push_back({"pts", false, false, false, false});
    out.push_back({"pts", false, false, false, true});
    return out;
}

class ioRoundTrip : public testing::TestWithParam<Case> {};

// Point tolerance: PCD stores float32; the text formats and PLY store doubles exactly (PLY ascii
// and the XYZ family print the shortest round-tripping decimal).
double point_tolerance(const Case& c) { return c.format == "pcd" ? 1e-6 : 0.0; }

void check(const Case& c, const PointCloud& in, const PointCloud& out) {
    expect_near(in.points, out.points, point_tolerance(c), "points");
    const bool keeps_normals = c.normals && c.format != "pts" && c.format != "xyz" && c.format != "xyzrgb";
    const bool keeps_colors = c.colors && c.format != "xyz" && c.format != "xyzn";
    EXPECT_EQ(out.has_normals(), keeps_normals);
    EXPECT_EQ(out.has_colors(), keeps_colors);
    if (keeps_normals) expect_near(in.normals, out.normals, point_tolerance(c), "normals");
    // Colours were made on the 1/255 grid, so uchar and packed-rgb storage give them back exactly.
    if (keeps_colors) expect_near(in.colors, out.colors, 1e-15, "colors");
}

TEST_P(ioRoundTrip, Memory) {
    const Case& c = GetParam();
    const PointCloud in = make_cloud(257, c.normals, c.colors);
    o3d::io::WriteOptions w;
    w.write_ascii = c.ascii;
    w.compressed = c.compressed;
    const std::vector<uint8_t> bytes = o3d::io::write_point_cloud_to_memory(in, c.format, w);
    ASSERT_FALSE(bytes.empty());
    check(c, in, o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), c.format));
}

TEST_P(ioRoundTrip, FileByExtension) {
    const Case& c = GetParam();
    const PointCloud in = make_cloud(100, c.normals, c.colors, 11);
    o3d::io::WriteOptions w;
    w.write_ascii = c.ascii;
    w.compressed = c.compressed;
    const std::string path = testing::TempDir() + "o3d_io_roundtrip_" + name_of(c) + "." + c.format;
    o3d::io::write_point_cloud(path, in, "auto", w);
    check(c, in, o3d::io::read_point_cloud(path));
    std::remove(path.c_str());
}

TEST_P(ioRoundTrip, EmptyCloud) {
    const Case& c = GetParam();
    o3d::io::WriteOptions w;
    w.write_ascii = c.ascii;
    w.compressed = c.compressed;
    const std::vector<uint8_t> bytes = o3d::io::write_point_cloud_to_memory(PointCloud{}, c.format, w);
    EXPECT_EQ(o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), c.format).size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, ioRoundTrip, testing::ValuesIn(all_cases()), case_name);

TEST(ioRoundTripDetail, PlyBinaryIsBitExactIncludingNonFinite) {
    PointCloud in = make_cloud(10, true, false);
    in.points[3].x() = std::numeric_limits<double>::quiet_NaN();
    in.points[4].y() = -std::numeric_limits<double>::infinity();
    in.points[5].z() = std::numeric_limits<double>::denorm_min();
    for (bool ascii : {false, true}) {
        o3d::io::WriteOptions w;
        w.write_ascii = ascii;
        const auto bytes = o3d::io::write_point_cloud_to_memory(in, "ply", w);
        const PointCloud out = o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), "ply");
        ASSERT_EQ(out.size(), in.size());
        EXPECT_TRUE(std::isnan(out.points[3].x()));
        EXPECT_EQ(out.points[4].y(), -std::numeric_limits<double>::infinity());
        EXPECT_EQ(out.points[5].z(), std::numeric_limits<double>::denorm_min());
        EXPECT_EQ(out.points[0], in.points[0]);
        EXPECT_EQ(out.normals[9], in.normals[9]);
    }
}

TEST(ioRoundTripDetail, ColorsAreQuantisedLikeOpen3D) {
    PointCloud in = make_cloud(4, false, true);
    in.colors[0] = Eigen::Vector3d(-0.5, 2.0, 0.5);  // clamped, then rounded: 0, 255, 128
    in.colors[1] = Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0.999, 0.001);
    for (const char* format : {"ply", "pcd", "pts"}) {
        const auto bytes = o3d::io::write_point_cloud_to_memory(in, format);
        const PointCloud out = o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), format);
        ASSERT_TRUE(out.has_colors()) << format;
        EXPECT_EQ(out.colors[0], Eigen::Vector3d(0, 1, 128 / 255.0)) << format;
        EXPECT_EQ(out.colors[1], Eigen::Vector3d(0, 1, 0)) << format;
    }
}

TEST(ioRoundTripDetail, PcdCompressedIsSmallerForRepetitiveData) {
    PointCloud in;
    for (int i = 0; i < 5000; ++i) in.points.emplace_back(i % 10, 0.5, 1.0);
    o3d::io::WriteOptions w;
    w.compressed = true;
    const auto packed = o3d::io::write_point_cloud_to_memory(in, "pcd", w);
    const auto plain = o3d::io::write_point_cloud_to_memory(in, "pcd");
    EXPECT_LT(packed.size() * 4, plain.size());
    const std::string text(packed.begin(), packed.end());
    EXPECT_NE(text.find("DATA binary_compressed\n"), std::string::npos);
    expect_near(in.points, o3d::io::read_point_cloud_from_memory(packed.data(), packed.size(), "pcd").points, 0.0,
                "points");
}

TEST(ioRoundTripDetail, LargeCloudBinaryFormats) {
    const PointCloud in = make_cloud(200000, true, true, 3);
    for (const char* format : {"ply", "pcd"}) {
        const auto bytes = o3d::io::write_point_cloud_to_memory(in, format);
        const PointCloud out = o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), format);
        ASSERT_EQ(out.size(), in.size()) << format;
        EXPECT_TRUE(out.has_normals() && out.has_colors()) << format;
        EXPECT_NEAR(out.points.back().x(), in.points.back().x(), 1e-4) << format;
    }
}

TEST(ioRoundTripDetail, WritersFollowOpen3DLayout) {
    const PointCloud in = make_cloud(3, true, true);
    const auto ply = o3d::io::write_point_cloud_to_memory(in, "ply");
    const std::string ply_text(ply.begin(), ply.end());
    EXPECT_EQ(ply_text.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
    EXPECT_NE(ply_text.find("property double x\n"), std::string::npos);
    EXPECT_NE(ply_text.find("property double nx\n"), std::string::npos);
    EXPECT_NE(ply_text.find("property uchar red\n"), std::string::npos);
    const size_t header = ply_text.find("end_header\n") + 11;
    EXPECT_EQ(ply.size() - header, 3u * (48 + 3));

    const auto pcd = o3d::io::write_point_cloud_to_memory(in, "pcd");
    const std::string pcd_text(pcd.begin(), pcd.end());
    EXPECT_NE(pcd_text.find("FIELDS x y z normal_x normal_y normal_z rgb\nSIZE 4 4 4 4 4 4 4\nTYPE F F F F F F F\n"),
              std::string::npos);
    EXPECT_NE(pcd_text.find("DATA binary\n"), std::string::npos);
    EXPECT_EQ(pcd.size() - (pcd_text.find("DATA binary\n") + 12), 3u * 28);
}

TEST(ioRoundTripDetail, XyznAndXyzrgbNeedTheirAttribute) {
    const PointCloud bare = make_cloud(3, false, false);
    EXPECT_THROW(o3d::io::write_point_cloud_to_memory(bare, "xyzn"), o3d::InvalidArgument);
    EXPECT_THROW(o3d::io::write_point_cloud_to_memory(bare, "xyzrgb"), o3d::InvalidArgument);
}

}  // namespace
