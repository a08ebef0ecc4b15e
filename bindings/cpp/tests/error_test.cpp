// SPDX-License-Identifier: MIT
// Failed C calls become o3dpp::Error carrying the status code and the library's message.
#include "test_util.hpp"

TEST(Error, MissingFileIsIoErrorNamingThePath) {
    const std::string path = o3dpp_test::tmp_path("does_not_exist.ply");
    try {
        o3dpp::read_point_cloud(path);
        FAIL() << "no exception";
    } catch (const o3dpp::Error& e) {
        EXPECT_EQ(e.code(), O3D_ERROR_IO);
        EXPECT_STREQ(e.code_name(), "O3D_ERROR_IO");
        EXPECT_NE(std::string(e.what()).find("does_not_exist.ply"), std::string::npos) << e.what();
        // The wrapper reports the same message the C API stored for this thread.
        EXPECT_EQ(std::string(e.what()), o3dpp::last_error_message());
        EXPECT_EQ(o3dpp::last_error_code(), O3D_ERROR_IO);
    }
}

TEST(Error, BadArgumentsAreInvalidArgument) {
    o3dpp::PointCloud pc(o3dpp_test::random_points(10));
    EXPECT_O3D_ERROR(pc.voxel_down_sample(-1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.voxel_down_sample(0.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.uniform_down_sample(0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR((pc.select_by_index({0, 10})), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::set_verbosity_level(static_cast<o3dpp::LogLevel>(7)), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Error, MalformedMemoryIsParseError) {
    EXPECT_O3D_ERROR(o3dpp::read_point_cloud_from_memory(std::string("ply\nformat nonsense\n"), "ply"),
                     O3D_ERROR_PARSE);
}

TEST(Error, UnknownFormatIsUnsupported) {
    o3dpp::PointCloud pc(o3dpp_test::random_points(3));
    EXPECT_O3D_ERROR(o3dpp::write_point_cloud_to_memory(pc, "no-such-format"), O3D_ERROR_UNSUPPORTED);
}

TEST(Error, BufferTooSmallThroughCheck) {
    o3dpp::PointCloud pc(o3dpp_test::random_points(5));
    double out[3 * 2];
    size_t n = 0;
    EXPECT_O3D_ERROR(o3dpp::check(o3d_pointcloud_get_array(out, 2, &n, pc.get(), O3D_POINTCLOUD_POINTS)), O3D_ERROR_BUFFER_TOO_SMALL);
    EXPECT_EQ(n, 5u);
}

TEST(Error, CheckOkDoesNothingAndErrorIsARuntimeError) {
    EXPECT_NO_THROW(o3dpp::check(O3D_OK));
    o3dpp::Error e(O3D_ERROR_INTERNAL, "boom");
    const std::runtime_error& base = e;
    EXPECT_STREQ(base.what(), "boom");
    EXPECT_EQ(e.code(), O3D_ERROR_INTERNAL);
    EXPECT_STREQ(o3dpp::status_string(O3D_ERROR_CANCELLED), "O3D_ERROR_CANCELLED");
}

TEST(Error, ClearErrorResetsState) {
    EXPECT_THROW(o3dpp::set_num_threads(-1), o3dpp::Error);
    EXPECT_NE(o3dpp::last_error_code(), O3D_OK);
    o3dpp::clear_error();
    EXPECT_EQ(o3dpp::last_error_code(), O3D_OK);
    EXPECT_EQ(o3dpp::last_error_message(), "");
}
