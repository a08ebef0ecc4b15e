// SPDX-License-Identifier: MIT
// Format names and extensions, files that cannot be opened, the file-versus-memory contract.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "io_test_util.h"

namespace {

using o3d::geometry::PointCloud;

std::string temp(const std::string& name) { return testing::TempDir() + "o3d_io_dispatch_" + name; }

TEST(ioDispatch, ExtensionPicksTheFormatCaseInsensitively) {
    const PointCloud in = o3d::test::make_cloud(5, true, false);
    const std::string path = temp("cloud.XYZN");
    o3d::io::write_point_cloud(path, in);
    std::ifstream f(path);
    std::string first;
    std::getline(f, first);
    // Six numbers per line: the xyzn writer ran.
    size_t columns = 0;
    for (size_t i = 0; i < first.size(); ++i) columns += first[i] != ' ' && (i == 0 || first[i - 1] == ' ');
    EXPECT_EQ(columns, 6u);
    EXPECT_TRUE(o3d::io::read_point_cloud(path).has_normals());
    std::remove(path.c_str());
}

TEST(ioDispatch, ExplicitFormatOverridesTheExtension) {
    const PointCloud in = o3d::test::make_cloud(5, false, false);
    const std::string path = temp("cloud.dat");
    o3d::io::write_point_cloud(path, in, "PCD");
    EXPECT_EQ(o3d::io::read_point_cloud(path, "pcd").size(), 5u);
    EXPECT_THROW(o3d::io::read_point_cloud(path), o3d::Unsupported);
    EXPECT_THROW(o3d::io::read_point_cloud(path, "ply"), o3d::ParseError);
    std::remove(path.c_str());
}

TEST(ioDispatch, UnknownFormatsAreUnsupported) {
    const PointCloud in = o3d::test::make_cloud(1, false, false);
    EXPECT_THROW(o3d::io::write_point_cloud_to_memory(in, "obj"), o3d::Unsupported);
    EXPECT_THROW(o3d::test::read_text("1 2 3", "las"), o3d::Unsupported);
    EXPECT_THROW(o3d::io::write_point_cloud(temp("noext"), in), o3d::Unsupported);
    EXPECT_THROW(o3d::io::read_point_cloud(temp("dir.d/cloud")), o3d::Unsupported);
}

TEST(ioDispatch, MemoryNeedsAFormat) {
    EXPECT_THROW(o3d::test::read_text("1 2 3", "auto"), o3d::InvalidArgument);
    EXPECT_THROW(o3d::test::read_text("1 2 3", ""), o3d::InvalidArgument);
    EXPECT_THROW(o3d::io::write_point_cloud_to_memory(PointCloud{}, "auto"), o3d::InvalidArgument);
    EXPECT_THROW(o3d::io::read_point_cloud_from_memory(nullptr, 3, "xyz"), o3d::InvalidArgument);
    EXPECT_EQ(o3d::io::read_point_cloud_from_memory(nullptr, 0, "xyz").size(), 0u);
}

TEST(ioDispatch, MissingFileIsAnIoErrorNamingIt) {
    const std::string path = temp("does_not_exist.ply");
    try {
        o3d::io::read_point_cloud(path);
        FAIL();
    } catch (const o3d::IoError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_THROW(o3d::io::read_point_cloud(testing::TempDir() + "/.", "ply"), o3d::IoError);  // a directory
    EXPECT_THROW(o3d::io::write_point_cloud("/nonexistent_dir_o3d/x.ply", PointCloud{}), o3d::IoError);
}

TEST(ioDispatch, ParseErrorsNameTheFile) {
    const std::string path = temp("broken.pcd");
    {
        std::ofstream f(path);
        f << "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 10\nDATA binary\nshort";
    }
    try {
        o3d::io::read_point_cloud(path);
        FAIL();
    } catch (const o3d::ParseError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("declares 10 points"), std::string::npos) << e.what();
    }
    std::remove(path.c_str());
}

TEST(ioDispatch, TextFormatsSkipCommentsAndBlankLines) {
    const auto pc = o3d::test::read_text("# scanner export\n\n1 2 3 extra columns ignored\r\n  \n4 5 6", "xyz");
    ASSERT_EQ(pc.size(), 2u);
    EXPECT_EQ(pc.points[1], Eigen::Vector3d(4, 5, 6));
}

TEST(ioDispatch, PtsVariants) {
    const auto i = o3d::test::read_text("2\n1 2 3 10\n4 5 6 20\n", "pts");
    EXPECT_EQ(i.size(), 2u);
    EXPECT_FALSE(i.has_colors());
    const auto irgb = o3d::test::read_text("1\n1 2 3 -1500 255 0 51\n", "pts");
    ASSERT_TRUE(irgb.has_colors());
    EXPECT_EQ(irgb.colors[0], Eigen::Vector3d(1, 0, 0.2));
    const auto rgb = o3d::test::read_text("1\n1 2 3 255 0 51\n", "pts");
    EXPECT_EQ(rgb.colors[0], Eigen::Vector3d(1, 0, 0.2));
    // Leica scans concatenate blocks, each with its own count.
    const auto blocks = o3d::test::read_text("1\n1 2 3\n2\n4 5 6\n7 8 9\n", "pts");
    ASSERT_EQ(blocks.size(), 3u);
    EXPECT_EQ(blocks.points[2], Eigen::Vector3d(7, 8, 9));
    EXPECT_EQ(o3d::test::read_text("0\n", "pts").size(), 0u);
}

}  // namespace
