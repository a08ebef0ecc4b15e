// SPDX-License-Identifier: MIT
// io through the wrapper: memory and file round trips in every format, options, real data.
#include <cmath>
#include <cstdio>

#include "test_util.hpp"

using o3dpp::Vec3;

namespace {
o3dpp::PointCloud sample_cloud() {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0.5, -1.25, 2.0}, {3.0, 4.0, 5.5}, {-7.0, 0.0, 0.125}});
    pc.set_normals(std::vector<Vec3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}});
    pc.set_colors(std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    return pc;
}
}  // namespace

TEST(IO, MemoryRoundTripPreservesAllAttributes) {
    const auto pc = sample_cloud();
    for (const char* format : {"ply", "pcd"}) {
        for (bool ascii : {false, true}) {
            o3dpp::WriteOptions opts;
            opts.write_ascii = ascii;
            auto buf = o3dpp::write_point_cloud_to_memory(pc, format, opts);
            EXPECT_GT(buf.size(), 0u);
            EXPECT_EQ(buf.to_vector().size(), buf.view().size());
            auto back = o3dpp::read_point_cloud_from_memory(buf.to_vector(), format);
            EXPECT_EQ(back.get_points(), pc.get_points()) << format << " ascii=" << ascii;
            EXPECT_EQ(back.get_normals(), pc.get_normals()) << format;
            auto colors = back.get_colors();
            ASSERT_EQ(colors.size(), 3u);
            for (size_t i = 0; i < 3; ++i)
                for (int k = 0; k < 3; ++k) EXPECT_NEAR(colors[i][k], pc.get_colors()[i][k], 1.0 / 255);
        }
    }
}

TEST(IO, XyzTextRoundTrip) {
    const auto pc = sample_cloud();
    auto buf = o3dpp::write_point_cloud_to_memory(pc, "xyz");
    EXPECT_NE(buf.to_string().find("0.5"), std::string::npos);
    auto back = o3dpp::read_point_cloud_from_memory(buf.to_string(), "xyz");
    EXPECT_EQ(back.get_points(), pc.get_points());
    EXPECT_FALSE(back.has_normals());
}

TEST(IO, FileRoundTripCompressedPcd) {
    const auto pc = sample_cloud();
    const std::string path = o3dpp_test::tmp_path("io_test_roundtrip.pcd");
    o3dpp::WriteOptions opts;
    opts.compressed = true;
    o3dpp::write_point_cloud(path, pc, "", opts);
    auto back = o3dpp::read_point_cloud(path);
    EXPECT_EQ(back.get_points(), pc.get_points());
    EXPECT_EQ(back.get_normals(), pc.get_normals());
    std::remove(path.c_str());
}

TEST(IO, ReadOptionsRemoveNonFinite) {
    const std::string text = "0 0 0\nnan 1 1\n2 2 2\ninf 0 0\n";
    EXPECT_EQ(o3dpp::read_point_cloud_from_memory(text, "xyz").size(), 4u);
    o3dpp::ReadOptions opts;
    opts.remove_nan_points = true;
    EXPECT_EQ(o3dpp::read_point_cloud_from_memory(text, "xyz", opts).size(), 3u);
    opts.remove_infinite_points = true;
    EXPECT_EQ(o3dpp::read_point_cloud_from_memory(text, "xyz", opts).get_points(),
              (std::vector<Vec3>{{0, 0, 0}, {2, 2, 2}}));
}

TEST(IO, ReadsRealPcd) {
    O3DPP_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    auto pc = o3dpp::read_point_cloud(path);
    EXPECT_EQ(pc.size(), 3903u);  // POINTS 3903 in the header
    EXPECT_TRUE(pc.has_normals());
    EXPECT_TRUE(pc.has_colors());
    for (const auto& p : pc.get_points())
        for (double v : p) ASSERT_TRUE(std::isfinite(v));
}
