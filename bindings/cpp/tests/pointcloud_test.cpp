// SPDX-License-Identifier: MIT
// PointCloud: setters/getters/views round trip, float input, clone, append, geometry helpers, duplicates.
#include <cmath>

#include "test_util.hpp"

using o3dpp::Vec3;

TEST(PointCloud, PointsRoundTripThroughCopyAndView) {
    const auto pts = o3dpp_test::random_points(100);
    o3dpp::PointCloud pc(pts);
    EXPECT_EQ(pc.size(), 100u);
    EXPECT_TRUE(pc.has_points());
    EXPECT_FALSE(pc.has_normals());
    EXPECT_FALSE(pc.has_colors());
    EXPECT_EQ(pc.get_points(), pts);
    const auto view = pc.points();
    ASSERT_EQ(view.size(), 100u);
    for (size_t i = 0; i < pts.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(view[i][k], pts[i][k]);
    EXPECT_EQ(view.flat().size(), 300u);
}

TEST(PointCloud, FloatInputIsConverted) {
    std::vector<std::array<float, 3>> f = {{0.5f, 1.25f, -2.0f}, {3.0f, 4.0f, 5.0f}};
    o3dpp::PointCloud pc;
    pc.set_points(f);
    pc.set_normals(f);
    pc.set_colors(std::vector<std::array<float, 3>>{{0.25f, 0.5f, 1.0f}, {0.0f, 0.0f, 0.0f}});
    EXPECT_EQ(pc.get_points(), (std::vector<Vec3>{{0.5, 1.25, -2.0}, {3.0, 4.0, 5.0}}));
    EXPECT_EQ(pc.get_normals(), pc.get_points());
    EXPECT_EQ(pc.get_colors()[0], (Vec3{0.25, 0.5, 1.0}));
    EXPECT_TRUE(pc.has_normals());
    EXPECT_TRUE(pc.has_colors());
}

TEST(PointCloud, MutableViewEditsInPlace) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{1, 2, 3}});
    auto v = pc.points_mutable();
    v[0][2] = 30.0;
    EXPECT_EQ(pc.get_points()[0], (Vec3{1, 2, 30}));
    pc.set_normals(std::vector<Vec3>{{0, 0, 1}});
    pc.normals_mutable()[0][0] = 1.0;
    EXPECT_EQ(pc.normals()[0][0], 1.0);
    pc.set_colors(std::vector<Vec3>{{0, 0, 0}});
    pc.colors_mutable()[0][1] = 0.5;
    EXPECT_EQ(pc.colors()[0][1], 0.5);
}

TEST(PointCloud, CloneIsDeep) {
    o3dpp::PointCloud a(std::vector<Vec3>{{1, 1, 1}});
    o3dpp::PointCloud b = a.clone();
    a.points_mutable()[0][0] = 9.0;
    EXPECT_EQ(b.get_points()[0], (Vec3{1, 1, 1}));
    EXPECT_NE(a.get(), b.get());
}

TEST(PointCloud, AppendConcatenates) {
    o3dpp::PointCloud a(std::vector<Vec3>{{0, 0, 0}});
    o3dpp::PointCloud b(std::vector<Vec3>{{1, 1, 1}, {2, 2, 2}});
    a += b;
    a.append(b);
    EXPECT_EQ(a.size(), 5u);
    EXPECT_EQ(a.get_points()[4], (Vec3{2, 2, 2}));
    a.clear();
    EXPECT_EQ(a.size(), 0u);
    EXPECT_TRUE(a.empty());
}

TEST(PointCloud, BoundsAndCenter) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {2, 4, 6}, {1, -1, 0}});
    EXPECT_EQ(pc.get_min_bound(), (Vec3{0, -1, 0}));
    EXPECT_EQ(pc.get_max_bound(), (Vec3{2, 4, 6}));
    EXPECT_EQ(pc.get_center(), (Vec3{1, 1, 2}));
    const auto box = pc.get_axis_aligned_bounding_box();
    EXPECT_EQ(box[0], pc.get_min_bound());
    EXPECT_EQ(box[1], pc.get_max_bound());
}

TEST(PointCloud, TransformTranslateRotateScale) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{1, 0, 0}, {-1, 0, 0}});
    pc.transform({1, 0, 0, 10, 0, 1, 0, 20, 0, 0, 1, 30, 0, 0, 0, 1});
    EXPECT_EQ(pc.get_points()[0], (Vec3{11, 20, 30}));
    pc.translate({0, 0, 0}, /*relative=*/false);
    EXPECT_EQ(pc.get_center(), (Vec3{0, 0, 0}));
    pc.translate({1, 1, 1});
    EXPECT_EQ(pc.get_points()[0], (Vec3{2, 1, 1}));
    // 90 degrees about z, about the center (1,1,1): (2,1,1) -> (1,2,1).
    pc.rotate({0, -1, 0, 1, 0, 0, 0, 0, 1});
    const auto p = pc.get_points()[0];
    EXPECT_NEAR(p[0], 1.0, 1e-12);
    EXPECT_NEAR(p[1], 2.0, 1e-12);
    pc.rotate({1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0});
    pc.scale(2.0);  // about center (1,1,1): (1,2,1) -> (1,3,1)
    EXPECT_NEAR(pc.get_points()[0][1], 3.0, 1e-12);
    pc.scale(0.5, {0, 0, 0});
    EXPECT_NEAR(pc.get_points()[0][1], 1.5, 1e-12);
}

TEST(PointCloud, PaintSelectRemoveNonFinite) {
    const double nan = std::nan("");
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {nan, 0, 0}, {2, 2, 2}, {INFINITY, 0, 0}});
    pc.paint_uniform_color({0.1, 0.2, 0.3});
    EXPECT_EQ(pc.get_colors()[3], (Vec3{0.1, 0.2, 0.3}));
    auto sel = pc.select_by_index({2});
    EXPECT_EQ(sel.get_points(), (std::vector<Vec3>{{2, 2, 2}}));
    auto rest = pc.select_by_index({2}, /*invert=*/true);
    EXPECT_EQ(rest.size(), 3u);
    pc.remove_non_finite_points();
    EXPECT_EQ(pc.get_points(), (std::vector<Vec3>{{0, 0, 0}, {2, 2, 2}}));
}

TEST(PointCloud, NormalizeAndOrientNormals) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 1}, {0, 0, -1}});
    pc.set_normals(std::vector<Vec3>{{0, 0, -3}, {0, 0, 2}});
    pc.normalize_normals();
    EXPECT_EQ(pc.get_normals(), (std::vector<Vec3>{{0, 0, -1}, {0, 0, 1}}));
    pc.orient_normals_to_align_with_direction({0, 0, 1});
    EXPECT_EQ(pc.get_normals(), (std::vector<Vec3>{{0, 0, 1}, {0, 0, 1}}));
    // Towards the origin: the point at z=+1 must look down, the one at z=-1 up.
    pc.orient_normals_towards_camera_location({0, 0, 0});
    EXPECT_EQ(pc.get_normals(), (std::vector<Vec3>{{0, 0, -1}, {0, 0, 1}}));
}

TEST(PointCloud, NearestNeighborAndCloudDistances) {
    o3dpp::PointCloud a(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {3, 0, 0}});
    EXPECT_EQ(a.compute_nearest_neighbor_distance(), (std::vector<double>{1, 1, 2}));
    o3dpp::PointCloud b(std::vector<Vec3>{{0, 0, 2}});
    const auto d = a.compute_point_cloud_distance(b, 1);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_DOUBLE_EQ(d[0], 2.0);
    EXPECT_DOUBLE_EQ(d[1], std::sqrt(5.0));
    EXPECT_DOUBLE_EQ(d[2], std::sqrt(13.0));
}

TEST(PointCloud, GenericArrayAccessorChecksTheRowWidth) {
    using A = o3dpp::PointCloudArray;
    o3dpp::PointCloud pc;
    pc.set_array(A::Points, std::vector<Vec3>{{1, 2, 3}, {4, 5, 6}});
    EXPECT_TRUE(pc.has_array(A::Points));
    EXPECT_FALSE(pc.has_array(A::Normals));
    EXPECT_EQ(pc.array_shape(A::Points), (std::array<std::size_t, 2>{2, 3}));
    EXPECT_EQ(pc.array_shape(A::Covariances)[1], 9u);
    EXPECT_EQ(pc.get_array<double>(A::Points), (std::vector<double>{1, 2, 3, 4, 5, 6}));
    // Rows of the wrong width are refused before anything is copied.
    EXPECT_O3D_ERROR(pc.get_array<o3dpp::Vec2>(A::Points), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.set_array(A::Normals, std::vector<o3dpp::Mat3>(2)), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.set_array(A::Normals, std::vector<double>{1, 2}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_FALSE(pc.has_normals());
    // Flat float values: whole rows, converted in the one copy.
    pc.set_array(A::Normals, std::vector<float>{0, 0, 1, 0, 1, 0});
    EXPECT_EQ(pc.get_normals()[1], (Vec3{0, 1, 0}));
    const auto view = pc.array(A::Normals);
    EXPECT_EQ(view.size(), 2u);
    EXPECT_EQ(view.cols(), 3u);
    EXPECT_EQ(view.flat().size(), 6u);
}

TEST(PointCloud, OptionDefaultsComeFromTheLibrary) {
    o3d_search_param_t lib;
    o3dpp::check(o3d_search_param_init(&lib, sizeof lib));
    const o3dpp::SearchParam param;
    EXPECT_EQ(static_cast<int32_t>(param.kind), lib.kind);
    EXPECT_EQ(param.knn, lib.knn);
    EXPECT_EQ(param.radius, lib.radius);
    EXPECT_EQ(o3dpp::SearchParam::Radius(0.5).knn, lib.knn);
    o3d_depth_to_cloud_options_t depth;
    o3dpp::check(o3d_depth_to_cloud_options_init(&depth, sizeof depth));
    const o3dpp::DepthToCloudOptions d;
    EXPECT_EQ(d.depth_scale, depth.depth_scale);
    EXPECT_EQ(d.depth_trunc, depth.depth_trunc);
    EXPECT_EQ(d.stride, depth.stride);
    EXPECT_EQ(d.project_valid_depth_only, depth.project_valid_depth_only != 0);
    // to_c() carries every field over.
    o3dpp::DepthToCloudOptions changed;
    changed.stride = 3;
    changed.project_valid_depth_only = false;
    EXPECT_EQ(changed.to_c().stride, 3);
    EXPECT_EQ(changed.to_c().project_valid_depth_only, 0);
}

TEST(PointCloud, RemoveDuplicatedPointsKeepsTheFirstOfEach) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {1, 2, 3}, {0, 0, 0}, {4, 5, 6}, {1, 2, 3}, {1, 2, 3.5}});
    pc.set_normals(std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}});
    pc.set_colors(std::vector<Vec3>{{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}, {0.4, 0, 0}, {0.5, 0, 0}});
    pc.remove_duplicated_points();
    EXPECT_EQ(pc.get_points(), (std::vector<Vec3>{{0, 0, 0}, {1, 2, 3}, {4, 5, 6}, {1, 2, 3.5}}));
    EXPECT_EQ(pc.get_normals(), (std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, -1}}));
    EXPECT_EQ(pc.get_colors(), (std::vector<Vec3>{{0, 0, 0}, {0.1, 0, 0}, {0.3, 0, 0}, {0.5, 0, 0}}));
    // Nothing left to remove: unchanged.
    pc.remove_duplicated_points();
    EXPECT_EQ(pc.size(), 4u);
    o3dpp::PointCloud moved = std::move(pc);
    EXPECT_O3D_ERROR(pc.remove_duplicated_points(), O3D_ERROR_INVALID_ARGUMENT);  // NULL handle
}
