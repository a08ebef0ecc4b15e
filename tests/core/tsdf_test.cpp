// SPDX-License-Identifier: MIT
// TSDF integration: marching cubes' topology, surfaces of analytic shapes from exact depth, the two volumes
// against each other, Open3D's tutorial frames against Open3D's own result, and bad frames.
// Reference numbers: Open3D 0.20.0 (pip wheel), tools/reference/record_tsdf.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <random>

#include "o3d/camera/intrinsic_presets.h"
#include "o3d/camera/trajectory_log_io.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/integration/marching_cubes_cases.h"
#include "o3d/integration/scalable_tsdf_volume.h"
#include "o3d/integration/surface_extraction.h"
#include "o3d/integration/uniform_tsdf_volume.h"
#include "o3d/io/image_io.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/odometry/odometry.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "test_data.h"
#include "tsdf_test_scenes.h"

namespace {

using namespace o3d;
using integration::ColorType;
using integration::ScalableTSDFVolume;
using integration::UniformTSDFVolume;

const uint8_t kOrange[3] = {200, 100, 50};

template <typename Volume>
void integrate_around(Volume& volume, const o3d_test::RayCaster& shape, double distance) {
    const camera::PinholeCameraIntrinsic k = o3d_test::small_camera();
    for (const Eigen::Vector3d& eye : o3d_test::eyes_around(distance)) {
        const Eigen::Matrix4d extrinsic = o3d_test::look_at_origin(eye);
        volume.integrate(o3d_test::render(shape, k, extrinsic, kOrange), k, extrinsic);
    }
}

std::vector<double> sorted_errors(const geometry::TriangleMesh& mesh,
                                  const std::function<double(const Eigen::Vector3d&)>& distance) {
    std::vector<double> errors;
    for (const Eigen::Vector3d& v : mesh.vertices) errors.push_back(distance(v));
    std::sort(errors.begin(), errors.end());
    return errors;
}

TEST(MarchingCubesCases, EveryTriangleSitsOnCrossedEdgesAndEveryCrossedEdgeIsUsed) {
    const auto& cases = integration::detail::cube_cases();
    EXPECT_EQ(cases[0].num_triangles, 0);
    EXPECT_EQ(cases[255].num_triangles, 0);
    for (int pattern = 1; pattern < 255; ++pattern) {
        std::array<int, 12> uses{};
        for (int i = 0; i < 3 * cases[size_t(pattern)].num_triangles; ++i) ++uses[size_t(cases[size_t(pattern)].edges[size_t(i)])];
        for (int e = 0; e < 12; ++e) {
            const int a = integration::detail::edge_corner(e), b = a | (1 << integration::detail::edge_axis(e));
            const bool crossed = ((pattern >> a) & 1) != ((pattern >> b) & 1);
            EXPECT_EQ(crossed, uses[size_t(e)] > 0) << "pattern " << pattern << " edge " << e;
        }
    }
    // One inside corner: a single triangle; the 4-corner face patterns: two.
    EXPECT_EQ(cases[1].num_triangles, 1);
    EXPECT_EQ(cases[0x0F].num_triangles, 2);
}

TEST(MarchingCubes, RandomFieldOverManyBlocksIsClosedAndConsistentlyWound) {
    // A random tsdf over 3 x 3 x 3 blocks of side 4, positive on the outer layer: its zero set is closed, so
    // marching cubes must give a watertight, orientable mesh across every block face.
    integration::detail::BlockMap map(4, 0.1, Eigen::Vector3d::Zero(), false);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    for (int bx = 0; bx < 3; ++bx)
        for (int by = 0; by < 3; ++by)
            for (int bz = 0; bz < 3; ++bz) {
                integration::detail::VoxelBlock& block = map.find_or_create(Eigen::Vector3i(bx, by, bz));
                for (size_t i = 0; i < block.tsdf.size(); ++i) {
                    const int x = int(i / 16), y = int(i / 4 % 4), z = int(i % 4);
                    const int gx = 4 * bx + x, gy = 4 * by + y, gz = 4 * bz + z;
                    const bool border = std::min({gx, gy, gz}) == 0 || std::max({gx, gy, gz}) == 11;
                    block.tsdf[i] = border ? 1.0f : value(rng);
                    block.weight[i] = 1.0f;
                }
            }
    o3d::utility::set_default_num_threads(4);
    const geometry::TriangleMesh mesh = integration::detail::marching_cubes(map);
    // The blocks are meshed in parallel and merged in key order: one thread gives the very same mesh.
    o3d::utility::set_default_num_threads(1);
    const geometry::TriangleMesh serial = integration::detail::marching_cubes(map);
    o3d::utility::set_default_num_threads(0);
    EXPECT_TRUE(serial.vertices == mesh.vertices);
    EXPECT_TRUE(serial.triangles == mesh.triangles);
    ASSERT_GT(mesh.triangles.size(), 500u);
    EXPECT_TRUE(geometry::is_edge_manifold(mesh, false));
    EXPECT_TRUE(geometry::is_vertex_manifold(mesh));
    // Consistently wound: every edge is walked once in each direction.
    std::map<std::pair<int, int>, int> walks;
    for (const Eigen::Vector3i& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++walks[{t(k), t((k + 1) % 3)}];
    for (const auto& [edge, count] : walks) {
        ASSERT_EQ(count, 1);
        ASSERT_EQ(walks.count({edge.second, edge.first}), 1u);
    }
    // Every vertex is on a voxel edge, between the voxel centres it interpolates.
    for (const Eigen::Vector3d& v : mesh.vertices) {
        const Eigen::Vector3d g = v / 0.1 - Eigen::Vector3d::Constant(0.5);
        int on_grid = 0;
        for (int i = 0; i < 3; ++i) on_grid += std::abs(g(i) - std::round(g(i))) < 1e-9;
        EXPECT_GE(on_grid, 2);
    }
}

TEST(UniformTSDFVolume, SphereFromExactDepthLiesOnTheSphere) {
    const double radius = 0.3;
    UniformTSDFVolume volume(1.0, 128, 0.04, ColorType::RGB8, Eigen::Vector3d::Constant(-0.5));
    integrate_around(volume, o3d_test::sphere(Eigen::Vector3d::Zero(), radius), 1.2);
    const geometry::TriangleMesh mesh = volume.extract_triangle_mesh();
    ASSERT_GT(mesh.vertices.size(), 10000u);
    const double voxel = volume.voxel_length();
    const std::vector<double> errors =
        sorted_errors(mesh, [&](const Eigen::Vector3d& v) { return std::abs(v.norm() - radius); });
    // Each voxel reads its nearest pixel, so a vertex can be off by up to half a voxel where rays graze the
    // sphere; most are far closer.
    EXPECT_LT(errors.back(), 0.5 * voxel);
    EXPECT_LT(errors[errors.size() / 2], 0.1 * voxel);
    EXPECT_TRUE(geometry::is_watertight(mesh));
    // Triangles face free space: their normals point away from the centre.
    for (const Eigen::Vector3i& t : mesh.triangles) {
        const Eigen::Vector3d n = (mesh.vertices[size_t(t(1))] - mesh.vertices[size_t(t(0))])
                                      .cross(mesh.vertices[size_t(t(2))] - mesh.vertices[size_t(t(0))]);
        ASSERT_GT(n.dot(mesh.vertices[size_t(t(0))]), 0.0);
    }
    // Every vertex carries the frames' colour.
    ASSERT_EQ(mesh.vertex_colors.size(), mesh.vertices.size());
    for (const Eigen::Vector3d& c : mesh.vertex_colors)
        ASSERT_TRUE(c.isApprox(Eigen::Vector3d(200, 100, 50) / 255.0, 1e-5));
    // Points with normals pointing outward.
    const geometry::PointCloud cloud = volume.extract_point_cloud();
    ASSERT_GT(cloud.points.size(), 5000u);
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        ASSERT_LT(std::abs(cloud.points[i].norm() - radius), 0.5 * voxel);
        ASSERT_GT(cloud.normals[i].dot(cloud.points[i].normalized()), 0.9);
    }
}

TEST(ScalableTSDFVolume, AgreesWithTheUniformVolume) {
    const o3d_test::RayCaster shape = o3d_test::sphere(Eigen::Vector3d(0.05, -0.02, 0.0), 0.3);
    UniformTSDFVolume uniform(1.0, 128, 0.04, ColorType::None, Eigen::Vector3d::Constant(-0.5));
    ScalableTSDFVolume scalable(1.0 / 128, 0.04, ColorType::None);
    integrate_around(uniform, shape, 1.2);
    integrate_around(scalable, shape, 1.2);
    const geometry::TriangleMesh a = uniform.extract_triangle_mesh(), b = scalable.extract_triangle_mesh();
    EXPECT_TRUE(b.vertex_colors.empty());
    // Same voxel grid and the same update: the same surface. Only a voxel whose centre rounds to another
    // pixel (the two volumes compute centres in another order) may differ, at the sphere's silhouettes.
    ASSERT_GT(a.vertices.size(), 10000u);
    EXPECT_NEAR(double(b.vertices.size()), double(a.vertices.size()), 1e-3 * double(a.vertices.size()));
    EXPECT_NEAR(double(b.triangles.size()), double(a.triangles.size()), 1e-3 * double(a.triangles.size()));
    const kdtree::KDTree uniform_vertices(a.vertices);
    size_t same = 0;
    for (const Eigen::Vector3d& v : b.vertices) {
        double d2 = 0;
        same += uniform_vertices.search_nearest(v, 0.05 * uniform.voxel_length(), d2) >= 0;
    }
    EXPECT_GT(double(same), 0.99 * double(b.vertices.size()));
    const double pa = double(uniform.extract_point_cloud().points.size());
    EXPECT_NEAR(double(scalable.extract_point_cloud().points.size()), pa, 1e-3 * pa);
}

TEST(ScalableTSDFVolume, BoxFromExactDepthLiesOnTheBox) {
    const Eigen::Matrix3d rotation =
        (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    const Eigen::Vector3d half(0.25, 0.15, 0.2);
    ScalableTSDFVolume volume(0.01, 0.04, ColorType::None);
    integrate_around(volume, o3d_test::box(rotation, half), 1.3);
    const geometry::TriangleMesh mesh = volume.extract_triangle_mesh();
    ASSERT_GT(mesh.vertices.size(), 5000u);
    const double voxel = volume.voxel_length();
    // Marching cubes cannot keep a sharp edge, and behind an edge the projective distance of a grazing view
    // is wrong: vertices within three voxels of an edge are judged apart from those on the faces.
    std::vector<double> on_faces, near_edges;
    for (const Eigen::Vector3d& v : mesh.vertices) {
        const Eigen::Vector3d q = (rotation.transpose() * v).cwiseAbs();
        bool near_edge = false;
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            near_edge |= std::hypot(q(i) - half(i), q(j) - half(j)) < 3 * voxel;
        }
        (near_edge ? near_edges : on_faces).push_back(o3d_test::box_surface_distance(rotation, half, v));
    }
    std::sort(on_faces.begin(), on_faces.end());
    std::sort(near_edges.begin(), near_edges.end());
    ASSERT_GT(on_faces.size(), 2 * near_edges.size());
    EXPECT_LT(on_faces.back(), 1.0 * voxel);
    EXPECT_LT(on_faces[on_faces.size() * 99 / 100], 0.5 * voxel);
    EXPECT_LT(on_faces[on_faces.size() / 2], 0.1 * voxel);
    EXPECT_LT(near_edges[near_edges.size() / 2], 0.5 * voxel);
}

TEST(ScalableTSDFVolume, MemoryFollowsTheSurface) {
    // Doubling a sphere's radius quadruples its surface and multiplies its volume by eight: the blocks
    // allocated follow the surface.
    auto blocks_for = [](double radius) {
        ScalableTSDFVolume volume(1.0 / 128, 0.02, ColorType::None, 8);
        integrate_around(volume, o3d_test::sphere(Eigen::Vector3d::Zero(), radius), 1.5);
        return double(volume.block_count());
    };
    const double small = blocks_for(0.2), large = blocks_for(0.4);
    EXPECT_GT(large / small, 3.0);
    EXPECT_LT(large / small, 5.0);
    ScalableTSDFVolume volume(1.0 / 128, 0.02, ColorType::None, 8);
    integrate_around(volume, o3d_test::sphere(Eigen::Vector3d::Zero(), 0.2), 1.5);
    volume.reset();
    EXPECT_EQ(volume.block_count(), 0u);
    EXPECT_TRUE(volume.extract_triangle_mesh().vertices.empty());
}

TEST(UniformTSDFVolume, VoxelViewsAndVolumeArrays) {
    UniformTSDFVolume volume(1.0, 32, 0.1, ColorType::Gray32, Eigen::Vector3d::Constant(-0.5));
    const camera::PinholeCameraIntrinsic k = o3d_test::small_camera();
    const Eigen::Matrix4d extrinsic = o3d_test::look_at_origin(Eigen::Vector3d(0, 0, -1.2));
    geometry::RGBDImage frame = o3d_test::render(o3d_test::sphere(Eigen::Vector3d::Zero(), 0.3), k, extrinsic, kOrange);
    frame.color = {k.width, k.height, 1, 4, std::vector<uint8_t>(size_t(k.width) * size_t(k.height) * 4)};
    for (int v = 0; v < k.height; ++v)
        for (int u = 0; u < k.width; ++u) *frame.color.pixel<float>(u, v) = 0.25f;
    volume.integrate(frame, k, extrinsic);
    const geometry::PointCloud voxels = volume.extract_voxel_point_cloud();
    const geometry::VoxelGrid grid = volume.extract_voxel_grid();
    ASSERT_GT(voxels.points.size(), 100u);
    ASSERT_EQ(grid.voxels.size(), voxels.points.size());
    const std::vector<float> tsdf = volume.extract_volume_tsdf(), color = volume.extract_volume_color();
    ASSERT_EQ(tsdf.size(), 2u * 32 * 32 * 32);
    for (size_t i = 0; i < grid.voxels.size(); ++i) {
        const Eigen::Vector3i g = grid.voxels[i].grid_index;
        const size_t index = (size_t(g.x()) * 32 + size_t(g.y())) * 32 + size_t(g.z());
        ASSERT_EQ(tsdf[2 * index + 1], 1.0f);
        ASSERT_NEAR(grid.voxels[i].color.x(), (tsdf[2 * index] + 1.0) / 2.0, 1e-6);
        ASSERT_TRUE(voxels.points[i].isApprox(Eigen::Vector3d::Constant(-0.5) + (g.cast<double>().array() + 0.5).matrix() / 32.0));
        ASSERT_FLOAT_EQ(color[3 * index], 0.25f);
        ASSERT_LT(std::abs(tsdf[2 * index]), 0.98f);
    }
}

TEST(TSDFVolume, BadFramesAreErrorsAndChangeNothing) {
    ScalableTSDFVolume volume(0.01, 0.04, ColorType::RGB8);
    const camera::PinholeCameraIntrinsic k = o3d_test::small_camera();
    const Eigen::Matrix4d extrinsic = o3d_test::look_at_origin(Eigen::Vector3d(0, 0, -1.2));
    const geometry::RGBDImage frame = o3d_test::render(o3d_test::sphere(Eigen::Vector3d::Zero(), 0.3), k, extrinsic, kOrange);
    geometry::RGBDImage gray = frame;
    gray.color = {k.width, k.height, 1, 4, std::vector<uint8_t>(size_t(k.width) * size_t(k.height) * 4)};
    EXPECT_THROW(volume.integrate(gray, k, extrinsic), InvalidArgument);  // RGB8 volume, intensity colour
    camera::PinholeCameraIntrinsic other = k;
    other.width = 640;
    EXPECT_THROW(volume.integrate(frame, other, extrinsic), InvalidArgument);
    Eigen::Matrix4d nan = extrinsic;
    nan(0, 3) = std::nan("");
    EXPECT_THROW(volume.integrate(frame, k, nan), InvalidArgument);
    geometry::RGBDImage uint16_depth = frame;
    uint16_depth.depth.bytes_per_channel = 2;
    EXPECT_THROW(volume.integrate(uint16_depth, k, extrinsic), InvalidArgument);
    EXPECT_EQ(volume.block_count(), 0u);
    EXPECT_THROW(ScalableTSDFVolume(0.0, 0.04, ColorType::None), InvalidArgument);
    EXPECT_THROW(ScalableTSDFVolume(0.01, std::nan(""), ColorType::None), InvalidArgument);
    EXPECT_THROW(UniformTSDFVolume(1.0, 0, 0.04, ColorType::None), InvalidArgument);
    // Depth that is NaN or infinite is skipped, not fused.
    geometry::RGBDImage holes = frame;
    for (int v = 0; v < k.height; ++v) *holes.depth.pixel<float>(k.width / 2, v) = std::nanf("");
    *holes.depth.pixel<float>(0, 0) = INFINITY;
    EXPECT_NO_THROW(volume.integrate(holes, k, extrinsic));
    EXPECT_GT(volume.extract_triangle_mesh().vertices.size(), 100u);
}

std::vector<geometry::RGBDImage> tutorial_frames(const std::string& root, camera::PinholeCameraTrajectory& poses) {
    std::ifstream in(root + "/RGBD/trajectory.log");
    std::stringstream text;
    text << in.rdbuf();
    poses = camera::parse_trajectory_log(text.str(), "trajectory.log");
    std::vector<geometry::RGBDImage> frames;
    for (size_t i = 0; i < poses.parameters.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof(name), "%05zu", i);
        geometry::RGBDOptions options;
        options.depth_trunc = 4.0;
        options.convert_rgb_to_intensity = false;
        frames.push_back(geometry::create_rgbd_from_color_and_depth(
            io::read_image(root + "/RGBD/color/" + name + ".jpg"), io::read_image(root + "/RGBD/depth/" + name + ".png"),
            options));
    }
    return frames;
}

TEST(TSDFVolume, OpenThreeDTutorialFramesMatchOpenThreeD) {
    O3D_TEST_DATA_OR_SKIP(root, "open3d");
    camera::PinholeCameraTrajectory poses;
    const std::vector<geometry::RGBDImage> frames = tutorial_frames(root, poses);
    ASSERT_EQ(frames.size(), 5u);
    const camera::PinholeCameraIntrinsic k = camera::intrinsic_preset(camera::IntrinsicPreset::PrimeSenseDefault);
    // Open3D's rgbd_integration tutorial settings. trajectory.log holds camera-to-world poses, which the
    // reader returns as extrinsics (world to camera).
    ScalableTSDFVolume scalable(4.0 / 512, 0.04, ColorType::RGB8);
    for (size_t i = 0; i < frames.size(); ++i) scalable.integrate(frames[i], k, poses.parameters[i].extrinsic);
    const geometry::TriangleMesh mesh = scalable.extract_triangle_mesh();
    // Open3D 0.20.0's ScalableTSDFVolume gives an empty mesh here. Its UniformTSDFVolume(4.0, 512, origin
    // (-3.5, -1.5, 0.5)), on the same voxel grid as the scalable volume and holding the whole room: 147927
    // vertices, 280605 triangles, 141105 points, vertex sum (-317931.69, 87716.19, 414032.66), mean colour
    // (0.8439, 0.7838, 0.7514).
    EXPECT_NEAR(double(mesh.vertices.size()), 147927.0, 0.002 * 147927);
    EXPECT_NEAR(double(mesh.triangles.size()), 280605.0, 0.002 * 280605);
    EXPECT_NEAR(double(scalable.extract_point_cloud().points.size()), 141105.0, 0.002 * 141105);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), colour = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        sum += mesh.vertices[i];
        colour += mesh.vertex_colors[i];
    }
    const double n = double(mesh.vertices.size());
    EXPECT_NEAR(sum.x() / n, -317931.69 / 147927, 2e-3);
    EXPECT_NEAR(sum.y() / n, 87716.19 / 147927, 2e-3);
    EXPECT_NEAR(sum.z() / n, 414032.66 / 147927, 2e-3);
    EXPECT_NEAR(colour.x() / n, 0.8439, 2e-3);
    EXPECT_NEAR(colour.y() / n, 0.7838, 2e-3);
    EXPECT_NEAR(colour.z() / n, 0.7514, 2e-3);
}

TEST(ScalableTSDFVolume, LivingRoomSequenceGivesItsRoom) {
    // The case: Open3D 0.20.0's ScalableTSDFVolume extracts an empty mesh from this sequence. Poses
    // come from o3d's own odometry, chained frame to frame as Open3D's make_fragments does.
    O3D_TEST_DATA_OR_SKIP(root, "livingroom1_clean_micro");
    const camera::PinholeCameraIntrinsic k = camera::intrinsic_preset(camera::IntrinsicPreset::PrimeSenseDefault);
    ScalableTSDFVolume volume(4.0 / 512, 0.04, ColorType::RGB8);
    geometry::RGBDImage previous;
    Eigen::Matrix4d world_to_camera = Eigen::Matrix4d::Identity();
    std::vector<Eigen::Matrix4d> extrinsics;
    std::vector<geometry::RGBDImage> frames;
    for (int i = 0; i < 12; ++i) {
        char name[16];
        std::snprintf(name, sizeof(name), "%05d", i);
        const geometry::Image color = io::read_image(root + "/image/" + name + ".jpg");
        const geometry::Image depth = io::read_image(root + "/depth/" + name + ".png");
        geometry::RGBDOptions options;
        const geometry::RGBDImage intensity = geometry::create_rgbd_from_color_and_depth(color, depth, options);
        options.convert_rgb_to_intensity = false;
        frames.push_back(geometry::create_rgbd_from_color_and_depth(color, depth, options));
        if (i > 0) {
            const odometry::OdometryResult step = odometry::compute_rgbd_odometry(
                previous, intensity, k, Eigen::Matrix4d::Identity(), odometry::Jacobian::HybridTerm, {});
            ASSERT_TRUE(step.success) << "frame " << i;
            world_to_camera = step.transformation * world_to_camera;
        }
        previous = intensity;
        extrinsics.push_back(world_to_camera);
        volume.integrate(frames.back(), k, world_to_camera);
    }
    const geometry::TriangleMesh mesh = volume.extract_triangle_mesh();
    ASSERT_GT(mesh.vertices.size(), 50000u);
    ASSERT_EQ(mesh.vertex_colors.size(), mesh.vertices.size());
    // The room is where the frames saw it: the first and last frames' depth points lie on the mesh.
    const kdtree::KDTree vertices(mesh.vertices);
    for (size_t f : {size_t(0), frames.size() - 1}) {
        const Eigen::Matrix4d camera_to_world = extrinsics[f].inverse();
        std::vector<double> distances;
        for (int v = 0; v < k.height; v += 8) {
            for (int u = 0; u < k.width; u += 8) {
                const float d = *frames[f].depth.pixel<float>(u, v);
                if (!(d > 0)) continue;
                const Eigen::Vector4d p((u - k.cx) * d / k.fx, (v - k.cy) * d / k.fy, d, 1.0);
                double d2 = 0;
                vertices.search_nearest((camera_to_world * p).head<3>(), 1.0, d2);
                distances.push_back(std::sqrt(d2));
            }
        }
        ASSERT_GT(distances.size(), 2000u);
        std::sort(distances.begin(), distances.end());
        EXPECT_LT(distances[distances.size() / 2], volume.voxel_length()) << "frame " << f;
        EXPECT_LT(distances[distances.size() * 9 / 10], 2 * volume.voxel_length()) << "frame " << f;
    }
}

}  // namespace
