// SPDX-License-Identifier: MIT
// Every point-cloud file of the shared test data reads with the point count its header (or its
// line count) announces, counted here independently of the reader.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "io_test_util.h"
#include "test_data.h"

namespace {

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

/// @brief The integer after `key` at the start of a header line, or -1.
long header_value(const std::string& text, const std::string& key) {
    const size_t at = text.find("\n" + key);
    if (at == std::string::npos) return -1;
    return std::stol(text.substr(at + 1 + key.size()));
}

class ioDataFile : public testing::TestWithParam<const char*> {};

TEST_P(ioDataFile, ReadsTheAnnouncedPointCount) {
    O3D_TEST_DATA_OR_SKIP(path, std::string("open3d/") + GetParam());
    const std::string text = slurp(path);
    const bool ply = path.size() > 4 && path.compare(path.size() - 4, 4, ".ply") == 0;
    const long expected = header_value(text, ply ? "element vertex " : "POINTS ");
    ASSERT_GT(expected, 0);
    const auto pc = o3d::io::read_point_cloud(path);
    EXPECT_EQ(pc.size(), static_cast<size_t>(expected));
    // Every coordinate of these files is finite.
    for (const auto& p : pc.points) ASSERT_TRUE(p.allFinite());
    // The file from disk and the same bytes from memory give the same cloud.
    const auto mem = o3d::test::read_text(text, ply ? "ply" : "pcd");
    EXPECT_EQ(mem.points, pc.points);
    EXPECT_EQ(mem.colors, pc.colors);
}

INSTANTIATE_TEST_SUITE_P(SharedData, ioDataFile,
                         testing::Values("fragment.pcd", "Feature/cloud_bin_0.pcd", "Feature/cloud_bin_1.pcd",
                                         "bathtub_0154.ply", "color.ply", "knot.ply", "sphere.ply",
                                         "test_sample_ascii.ply", "test_sample_custom.ply"));

TEST(ioDataFiles, FragmentHasNormalsAndColors) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/fragment.pcd");
    const auto pc = o3d::io::read_point_cloud(path);
    ASSERT_EQ(pc.size(), 113662u);
    EXPECT_TRUE(pc.has_normals());
    EXPECT_TRUE(pc.has_colors());
    for (size_t i = 0; i < pc.size(); i += 97) {
        EXPECT_NEAR(pc.normals[i].norm(), 1.0, 1e-3) << i;
        EXPECT_TRUE((pc.colors[i].array() >= 0).all() && (pc.colors[i].array() <= 1).all()) << i;
    }
}

TEST(ioDataFiles, MeshPlyGivesItsVerticesWithNormalsAndColors) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/color.ply");
    const auto pc = o3d::io::read_point_cloud(path);
    EXPECT_EQ(pc.size(), 3017u);
    EXPECT_TRUE(pc.has_normals());
    EXPECT_TRUE(pc.has_colors());  // uchar red green blue (alpha ignored)
}

TEST(ioDataFiles, AsciiPlyValues) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/test_sample_ascii.ply");
    const auto pc = o3d::io::read_point_cloud(path);
    ASSERT_EQ(pc.size(), 7u);
    EXPECT_EQ(pc.points[1], Eigen::Vector3d(0.053054, 8.38004, -0.198));
    EXPECT_EQ(pc.points[6], Eigen::Vector3d(0.198, 8.38004, -0.053054));
}

// Open3D's own test reads this file and only checks that "intensity" (a char property between
// the coordinates and the normals) is not exposed: the file is valid PLY. Its two vertices and
// normals must come through with the char skipped.
TEST(ioDataFiles, WrongFormatSampleSkipsTheCharProperty) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/test_sample_wrong_format.ply");
    const auto pc = o3d::io::read_point_cloud(path);
    ASSERT_EQ(pc.size(), 2u);
    ASSERT_TRUE(pc.has_normals());
    EXPECT_EQ(pc.points[1], Eigen::Vector3d(0.7236, -0.52572, -0.447215));
    EXPECT_EQ(pc.normals[0], Eigen::Vector3d(0.003695, 0, -4.16078));
}

// ... but read as what it is not, it fails with a parse error naming the file.
TEST(ioDataFiles, WrongFormatSampleFailsAsPcd) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/test_sample_wrong_format.ply");
    try {
        o3d::io::read_point_cloud(path, "pcd");
        FAIL() << "read a PLY file as PCD";
    } catch (const o3d::ParseError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

TEST(ioDataFiles, SimpleXyz) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/simple.xyz");
    const auto pc = o3d::io::read_point_cloud(path);
    ASSERT_EQ(pc.size(), 4u);  // four lines of x y z
    EXPECT_EQ(pc.points[3], Eigen::Vector3d(0, 0, 1));
}

// my_points.txt holds x y z rows but its extension names no format: auto fails, "xyz" reads it.
TEST(ioDataFiles, MyPointsTxtNeedsAnExplicitFormat) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/my_points.txt");
    EXPECT_THROW(o3d::io::read_point_cloud(path), o3d::Unsupported);
    EXPECT_EQ(o3d::io::read_point_cloud(path, "xyz").size(), 4u);
}

}  // namespace
