// SPDX-License-Identifier: MIT
// SelectionPolygonVolume through the wrapper: analytic crops of a grid and a two-triangle mesh by a unit-square
// prism, Open3D's reference crop of its fragment, the errors thrown, and a VisualizerWithEditing crop driven
// by keys and the mouse in a hidden window.
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "test_util.hpp"

using o3dpp::Axis;
using o3dpp::KeyAction;
using o3dpp::MouseButton;
using o3dpp::PointCloud;
using o3dpp::SelectionPolygonVolume;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;

namespace {

// 30 x 30 points of step 0.1 from -0.95 at height z: 10 x 10 of them fall in (0, 1)^2, none on its edges.
PointCloud grid(double z) {
    std::vector<Vec3> points;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j) points.push_back({-0.95 + 0.1 * i, -0.95 + 0.1 * j, z});
    return PointCloud(points);
}

// The unit square across Z, over z in [0, 1].
SelectionPolygonVolume unit_square() {
    SelectionPolygonVolume v;
    v.set_orthogonal_axis(Axis::Z).set_axis_min(0.0).set_axis_max(1.0);
    v.set_bounding_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    return v;
}

}  // namespace

TEST(Selection, AccessorsRoundTrip) {
    SelectionPolygonVolume v;
    EXPECT_EQ(v.get_orthogonal_axis(), Axis::Y);  // the C default
    EXPECT_TRUE(v.get_bounding_polygon().empty());
    const SelectionPolygonVolume square = unit_square();
    EXPECT_EQ(square.get_orthogonal_axis(), Axis::Z);
    EXPECT_EQ(square.get_axis_min(), 0.0);
    EXPECT_EQ(square.get_axis_max(), 1.0);
    const std::vector<Vec3> corners = square.get_bounding_polygon();
    ASSERT_EQ(corners.size(), 4u);
    EXPECT_EQ(corners[2], (Vec3{1, 1, 0}));
}

TEST(Selection, CropsGridAnalytically) {
    const SelectionPolygonVolume v = unit_square();
    const PointCloud inside = v.crop_point_cloud(grid(0.5));
    ASSERT_EQ(inside.size(), 100u);
    for (const Vec3& p : inside.get_points()) {
        EXPECT_GT(p[0], 0.0);
        EXPECT_LT(p[0], 1.0);
        EXPECT_GT(p[1], 0.0);
        EXPECT_LT(p[1], 1.0);
    }
    EXPECT_EQ(v.crop_point_cloud(grid(1.5)).size(), 0u);  // above axis_max
    const std::vector<int32_t> idx = v.crop_in_polygon(grid(0.5));
    ASSERT_EQ(idx.size(), 100u);
    EXPECT_EQ(idx.front(), 10 * 30 + 10);  // grid (10, 10) is (0.05, 0.05)
    EXPECT_EQ(idx.back(), 19 * 30 + 19);   // grid (19, 19) is (0.95, 0.95)
}

TEST(Selection, MeshKeepsTrianglesWithAllVerticesInside) {
    // Vertex 3 is outside the square: triangle (1, 3, 2) goes, triangle (0, 1, 2) stays with its 3 vertices.
    const TriangleMesh mesh({{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}, {1.5, 0.9, 0.5}}, {{0, 1, 2}, {1, 3, 2}});
    const TriangleMesh cropped = unit_square().crop_triangle_mesh(mesh);
    EXPECT_EQ(cropped.num_triangles(), 1u);
    EXPECT_EQ(cropped.num_vertices(), 3u);
}

TEST(Selection, Open3DFragmentReference) {
    O3DPP_DATA_OR_SKIP(json, "open3d/Crop/cropped.json");
    O3DPP_DATA_OR_SKIP(pcd, "open3d/fragment.pcd");
    const SelectionPolygonVolume v = SelectionPolygonVolume::read_json(json);
    EXPECT_EQ(v.get_orthogonal_axis(), Axis::Y);
    EXPECT_NEAR(v.get_axis_min(), -0.76341366767883301, 1e-15);
    EXPECT_NEAR(v.get_axis_max(), 4.022921085357666, 1e-15);
    EXPECT_EQ(v.get_bounding_polygon().size(), 20u);
    const PointCloud cloud = o3dpp::read_point_cloud(pcd);
    ASSERT_EQ(cloud.size(), 113662u);
    const PointCloud cropped = v.crop_point_cloud(cloud);
    EXPECT_EQ(cropped.size(), 29873u);
    EXPECT_EQ(v.crop_in_polygon(cloud).size(), 29873u);
}

TEST(Selection, ErrorsThrow) {
    SelectionPolygonVolume v;
    EXPECT_O3D_ERROR(v.crop_point_cloud(grid(0.0)), O3D_ERROR_INVALID_ARGUMENT);  // no polygon yet
    EXPECT_O3D_ERROR(v.set_orthogonal_axis(static_cast<Axis>(3)), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(v.set_axis_min(std::numeric_limits<double>::quiet_NaN()), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(v.set_bounding_polygon({{0, 0, 0}, {1, INFINITY, 0}, {1, 1, 0}}), O3D_ERROR_INVALID_ARGUMENT);
    v.set_bounding_polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).set_axis_min(2.0).set_axis_max(1.0);
    EXPECT_O3D_ERROR(v.crop_in_polygon(grid(0.0)), O3D_ERROR_INVALID_ARGUMENT);  // axis_min > axis_max
    EXPECT_O3D_ERROR(SelectionPolygonVolume::read_json("/nonexistent/volume.json"), O3D_ERROR_IO);
}

TEST(Selection, VisualizerCropsTheDraggedRectangle) {
    o3dpp::Visualizer vis(true);
    vis.create_window("crop", 160, 120, -1, -1, false);
    const PointCloud cloud = grid(0.0);
    vis.add("grid", cloud);
    const std::string dir = o3dpp_test::tmp_path("selection_crops");
    std::filesystem::create_directories(dir);
    std::filesystem::remove(dir + "/cropped_1.ply");
    vis.set_crop_directory(dir);
    EXPECT_FALSE(vis.cropped_point_cloud().has_value());  // nothing cropped yet
    EXPECT_O3D_ERROR(vis.crop_to_selection(), O3D_ERROR_INVALID_ARGUMENT);  // no selection

    vis.send_key('K', KeyAction::Press);
    EXPECT_TRUE(vis.is_selecting());
    vis.send_mouse_move(50, 40).send_mouse_button(MouseButton::Left, KeyAction::Press);
    vis.send_mouse_move(80, 60).send_mouse_move(110, 80).send_mouse_button(MouseButton::Left, KeyAction::Release);
    vis.send_key('C', KeyAction::Press);
    EXPECT_FALSE(vis.is_selecting());

    const std::optional<PointCloud> cropped = vis.cropped_point_cloud();
    ASSERT_TRUE(cropped.has_value());
    EXPECT_GT(cropped->size(), 0u);
    EXPECT_LT(cropped->size(), cloud.size());
    EXPECT_FALSE(vis.cropped_triangle_mesh().has_value());  // the crop was of a cloud
    EXPECT_EQ(o3dpp::read_point_cloud(dir + "/cropped_1.ply").size(), cropped->size());  // also written there
}
