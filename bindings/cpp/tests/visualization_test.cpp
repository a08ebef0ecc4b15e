// SPDX-License-Identifier: MIT
// OffscreenRenderer through the wrapper: pixels against a known pinhole camera. The scene is a unit box
// [-0.5, 0.5]^2 x [2.5, 3.5] seen from the origin along +z with fx = fy = 100 and the principal point at
// the image centre (79.5, 59.5) of a 160 x 120 image, so its front face (z = 2.5) covers the 40 x 40
// pixels 60..99 x 40..79, and the depth along the axis there is 2.5.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "test_util.hpp"

using o3dpp::ColorOption;
using o3dpp::Image;
using o3dpp::LineSet;
using o3dpp::Mat4;
using o3dpp::OffscreenRenderer;
using o3dpp::PinholeIntrinsic;
using o3dpp::PointCloud;
using o3dpp::RenderBackend;
using o3dpp::RenderMaterial;
using o3dpp::RenderOption;
using o3dpp::Shader;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;
using o3dpp::VoxelGrid;

namespace {

constexpr int W = 160, H = 120;
constexpr int CU = 80, CV = 60;  // a pixel on the box's front face, next to the optical axis
const Vec3 kBoxColor{0.2, 0.4, 0.6};

PinholeIntrinsic camera_k() { return PinholeIntrinsic(W, H, 100, 100, 79.5, 59.5); }

TriangleMesh box(const Vec3& color = kBoxColor) {
    TriangleMesh b = TriangleMesh::create_box(1, 1, 1);
    b.translate({-0.5, -0.5, 2.5});
    b.paint_uniform_color(color);
    return b;
}

/// A renderer looking through camera_k() from the origin (identity extrinsic).
OffscreenRenderer pinhole_renderer() {
    OffscreenRenderer r(W, H);
    r.setup_camera(camera_k(), o3dpp::identity4());
    return r;
}

struct Rgb {
    int r, g, b;
};
Rgb pixel(const Image& img, int u, int v) {
    const auto d = img.data();
    const std::size_t i = (static_cast<std::size_t>(v) * W + u) * 3;
    return {d[i], d[i + 1], d[i + 2]};
}
float depth_at(const std::vector<float>& depth, int u, int v) { return depth[static_cast<std::size_t>(v) * W + u]; }

/// `color` in [0, 1] as 8-bit, within one step (rounding or truncation).
void expect_rgb(const Rgb& got, const Vec3& color, const char* what) {
    EXPECT_NEAR(got.r, 255 * color[0], 1.0) << what;
    EXPECT_NEAR(got.g, 255 * color[1], 1.0) << what;
    EXPECT_NEAR(got.b, 255 * color[2], 1.0) << what;
}
void expect_corners(const Image& img, const Vec3& color) {
    for (const auto& uv : {std::pair<int, int>{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}})
        expect_rgb(pixel(img, uv.first, uv.second), color, "corner");
}
/// Pixels that differ from `background` by more than one step in some channel.
int count_not(const Image& img, const Vec3& background) {
    int n = 0;
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) {
            const Rgb p = pixel(img, u, v);
            n += std::abs(p.r - 255 * background[0]) > 1 || std::abs(p.g - 255 * background[1]) > 1 ||
                 std::abs(p.b - 255 * background[2]) > 1;
        }
    return n;
}

const Vec3 kWhite{1, 1, 1};

}  // namespace

TEST(Visualization, OptionAndMaterialDefaultsAreOpen3Ds) {
    const RenderOption o;
    EXPECT_EQ(o.background_color, kWhite);
    EXPECT_EQ(o.point_size, 5.0);
    EXPECT_EQ(o.line_width, 1.0);
    EXPECT_TRUE(o.light_on);
    EXPECT_FALSE(o.mesh_show_back_face);
    EXPECT_EQ(o.mesh_shade_option, o3dpp::MeshShadeOption::Flat);
    EXPECT_EQ(o.point_color_option, ColorOption::Default);
    EXPECT_EQ(o.mesh_color_option, ColorOption::Color);
    EXPECT_EQ(o.default_mesh_color, (Vec3{0.7, 0.7, 0.7}));
    EXPECT_EQ(o.light_position[2], 2.0);
    EXPECT_EQ(o.light_position[11], -2.0);
    EXPECT_EQ(o.light_diffuse_power[3], 0.66);
    const RenderMaterial m;
    EXPECT_EQ(m.shader, Shader::DefaultLit);
    EXPECT_EQ(m.base_color, (std::array<double, 4>{1, 1, 1, 1}));
    EXPECT_EQ(m.point_size, 0.0);
    EXPECT_EQ(RenderMaterial(Shader::DefaultUnlit).shader, Shader::DefaultUnlit);
}

TEST(Visualization, OptionJsonRoundTripAndOpen3DFile) {
    RenderOption o;
    o.background_color = {0.1, 0.2, 0.3};
    o.point_size = 7;
    o.mesh_show_wireframe = true;
    o.mesh_color_option = ColorOption::ZCoordinate;
    o.light_color[4] = 0.5;
    const std::string path = o3dpp_test::tmp_path("visualization_option.json");
    o.save_to_json(path);
    const RenderOption back = RenderOption().load_from_json(path);
    EXPECT_EQ(back.background_color, o.background_color);
    EXPECT_EQ(back.point_size, 7.0);
    EXPECT_TRUE(back.mesh_show_wireframe);
    EXPECT_EQ(back.mesh_color_option, ColorOption::ZCoordinate);
    EXPECT_EQ(back.light_color, o.light_color);
    std::remove(path.c_str());
    EXPECT_O3D_ERROR(RenderOption().load_from_json(o3dpp_test::tmp_path("no_such_option.json")), O3D_ERROR_IO);

    O3DPP_DATA_OR_SKIP(open3d, "open3d/renderoption.json");
    // Open3D's file differs from the defaults only in point_color_option (9, Normal).
    const RenderOption file = RenderOption().load_from_json(open3d);
    EXPECT_EQ(file.point_color_option, ColorOption::Normal);
    EXPECT_EQ(file.background_color, kWhite);
    EXPECT_EQ(file.light_specular_shininess, (std::array<double, 4>{100, 100, 100, 100}));
}

TEST(Visualization, UnlitBoxColorDepthAndSilhouetteUnderAPinholeCamera) {
    OffscreenRenderer r = pinhole_renderer();
    EXPECT_TRUE(r.backend() == RenderBackend::Egl || r.backend() == RenderBackend::Glfw);
    EXPECT_EQ(r.size(), (std::pair<int, int>{W, H}));
    r.add("box", box(), RenderMaterial(Shader::DefaultUnlit));

    const Image img = r.render_to_image();
    ASSERT_EQ(img.width(), W);
    ASSERT_EQ(img.height(), H);
    ASSERT_EQ(img.num_channels(), 3);
    ASSERT_EQ(img.bytes_per_channel(), 1);
    expect_corners(img, kWhite);
    expect_rgb(pixel(img, CU, CV), kBoxColor, "box centre");
    expect_rgb(pixel(img, 61, 41), kBoxColor, "inside the top-left corner of the face");
    expect_rgb(pixel(img, 58, CV), kWhite, "left of the face");
    expect_rgb(pixel(img, CU, 81), kWhite, "below the face");
    // The silhouette is the front face: 40 x 40 pixels.
    EXPECT_NEAR(count_not(img, kWhite), 1600, 0.02 * 1600);

    const auto metric = r.render_to_depth_image(true).to_values<float>();
    EXPECT_NEAR(depth_at(metric, CU, CV), 2.5, 1e-3);
    EXPECT_NEAR(depth_at(metric, 61, 41), 2.5, 1e-3);  // a plane facing the camera: same z everywhere
    EXPECT_EQ(depth_at(metric, 0, 0), 0.0f);
    const auto buffer = r.render_to_depth_image(false).to_values<float>();
    EXPECT_GT(depth_at(buffer, CU, CV), 0.0f);
    EXPECT_LT(depth_at(buffer, CU, CV), 1.0f);
    EXPECT_EQ(depth_at(buffer, W - 1, H - 1), 1.0f);

    const auto cam = r.camera();
    EXPECT_EQ(cam.intrinsic, camera_k());
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(cam.extrinsic[i], o3dpp::identity4()[i], 1e-12) << i;
}

TEST(Visualization, BackgroundTintAndAmbientOnlyLight) {
    OffscreenRenderer r = pinhole_renderer();
    RenderOption o;
    o.background_color = {0.1, 0.2, 0.3};
    r.set_render_option(o);
    EXPECT_EQ(r.render_option().background_color, o.background_color);
    RenderMaterial tinted(Shader::DefaultUnlit);
    tinted.base_color = {0.5, 1, 1, 1};
    r.add("box", box(), tinted);
    Image img = r.render_to_image();
    expect_corners(img, o.background_color);
    expect_rgb(pixel(img, CU, CV), {0.1, 0.4, 0.6}, "tinted box");

    // Lit with only ambient light: color * ambient (the header's formula with every light at power 0).
    o.light_on = true;
    o.light_ambient_color = {0.5, 0.5, 0.5};
    o.light_diffuse_power = {0, 0, 0, 0};
    o.light_specular_power = {0, 0, 0, 0};
    r.set_render_option(o);
    r.clear().add("box", box(), RenderMaterial());
    img = r.render_to_image();
    expect_rgb(pixel(img, CU, CV), {0.1, 0.2, 0.3}, "ambient-lit box");
}

TEST(Visualization, SceneAddHasRemoveClear) {
    OffscreenRenderer r = pinhole_renderer();
    EXPECT_FALSE(r.has("box"));
    r.add("box", box(), RenderMaterial(Shader::DefaultUnlit));
    EXPECT_TRUE(r.has("box"));
    EXPECT_O3D_ERROR(r.add("box", box()), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(r.add("", box()), O3D_ERROR_INVALID_ARGUMENT);
    r.remove("box");
    EXPECT_FALSE(r.has("box"));
    EXPECT_O3D_ERROR(r.remove("box"), O3D_ERROR_INVALID_ARGUMENT);
    expect_rgb(pixel(r.render_to_image(), CU, CV), kWhite, "removed box");

    // Geometries are copies: changing the mesh after adding it does not show.
    TriangleMesh mesh = box();
    r.add("a", mesh, RenderMaterial(Shader::DefaultUnlit));
    mesh.paint_uniform_color({1, 0, 0});
    expect_rgb(pixel(r.render_to_image(), CU, CV), kBoxColor, "the copy added");
    r.add("b", box(), RenderMaterial(Shader::DefaultUnlit));
    r.clear();
    EXPECT_FALSE(r.has("a"));
    EXPECT_FALSE(r.has("b"));
    EXPECT_EQ(count_not(r.render_to_image(), kWhite), 0);
}

TEST(Visualization, PointCloudLineSetAndVoxelGridOnTheAxis) {
    OffscreenRenderer r = pinhole_renderer();
    const RenderMaterial unlit(Shader::DefaultUnlit);

    PointCloud cloud({{0, 0, 2.5}});
    cloud.paint_uniform_color({1, 0, 0});
    RenderMaterial big = unlit;
    big.point_size = 9;  // a 9-pixel square around the axis
    r.add("cloud", cloud, big);
    Image img = r.render_to_image();
    expect_rgb(pixel(img, CU, CV), {1, 0, 0}, "point");
    expect_rgb(pixel(img, CU + 10, CV), kWhite, "beside the point");

    // A horizontal line through the axis, 5 pixels wide.
    LineSet line({{-1, 0, 2.5}, {1, 0, 2.5}}, {{0, 1}});
    line.paint_uniform_color({0, 1, 0});
    RenderMaterial wide = unlit;
    wide.line_width = 5;
    r.clear().add("line", line, wide);
    img = r.render_to_image();
    expect_rgb(pixel(img, CU, CV), {0, 1, 0}, "line");
    expect_rgb(pixel(img, CU + 30, CV), {0, 1, 0}, "line, 30 pixels along");
    expect_rgb(pixel(img, CU, CV + 10), kWhite, "below the line");

    // One voxel of edge 1 around (0, 0, 3): the unit box again.
    PointCloud centre({{0, 0, 3}});
    centre.paint_uniform_color({0, 0, 1});
    r.clear().add("grid", VoxelGrid::create_from_point_cloud(centre, 1.0), unlit);
    img = r.render_to_image();
    expect_rgb(pixel(img, CU, CV), {0, 0, 1}, "voxel");
    EXPECT_NEAR(count_not(img, kWhite), 1600, 0.02 * 1600);
    EXPECT_NEAR(depth_at(r.render_to_depth_image(true).to_values<float>(), CU, CV), 2.5, 1e-3);
}

// The renderer draws a large cloud in its own (spatial) order: the picture must not depend on the order the
// points come in. Depths are distinct, so no two points tie on a pixel.
TEST(Visualization, ACloudsPictureDoesNotDependOnItsPointOrder) {
    std::vector<Vec3> points, colors;
    std::uint32_t state = 12345;
    auto uniform = [&] {  // a small LCG: the test needs no library's generator
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / double(1 << 24);
    };
    for (int i = 0; i < 20000; ++i) {
        points.push_back({uniform() - 0.5, uniform() - 0.5, 2.5 + 1e-5 * i});
        colors.push_back({uniform(), uniform(), uniform()});
    }
    std::vector<Vec3> points_rev(points.rbegin(), points.rend()), colors_rev(colors.rbegin(), colors.rend());
    const RenderMaterial unlit(Shader::DefaultUnlit);
    auto render = [&](const std::vector<Vec3>& p, const std::vector<Vec3>& c) {
        PointCloud cloud(p);
        cloud.set_colors(c);
        OffscreenRenderer r = pinhole_renderer();
        r.add("cloud", cloud, unlit);
        return r.render_to_image();
    };
    const Image forward = render(points, colors), backward = render(points_rev, colors_rev);
    EXPECT_GT(count_not(forward, kWhite), 1600);  // the cloud covers the 40 x 40 pixels of the square, and more
    const auto a = forward.data(), b = backward.data();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin()));
}

TEST(Visualization, FovAndLookatCamerasLookAtTheBox) {
    OffscreenRenderer r(W, H);
    r.add("box", box(), RenderMaterial(Shader::DefaultUnlit));

    // From the origin towards +z with image-down = world +y: the pinhole camera above, as a field of view.
    const double fov = 2 * std::atan(60.0 / 100.0) * 180 / std::acos(-1.0);  // fy = (H / 2) / tan(fov / 2) = 100
    r.setup_camera(fov, {0, 0, 3}, {0, 0, 0}, {0, -1, 0});
    auto cam = r.camera();
    EXPECT_NEAR(cam.intrinsic.fy, 100, 1e-6);
    EXPECT_NEAR(cam.intrinsic.fx, 100, 1e-6);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(cam.extrinsic[i], o3dpp::identity4()[i], 1e-9) << i;
    EXPECT_NEAR(depth_at(r.render_to_depth_image(true).to_values<float>(), CU, CV), 2.5, 1e-3);

    // Open3D's view, looking at a point off the box's centre from -z (zoom 2: the box stays inside the
    // image): that point projects on the optical axis, in front of the camera.
    const Vec3 at{0.2, 0.1, 3};
    r.setup_camera_lookat(at, {0, 0, -1}, {0, -1, 0}, 2.0);
    cam = r.camera();
    const Mat4& e = cam.extrinsic;
    auto row = [&](int i) { return e[4 * i] * at[0] + e[4 * i + 1] * at[1] + e[4 * i + 2] * at[2] + e[4 * i + 3]; };
    EXPECT_NEAR(row(0), 0, 1e-9);
    EXPECT_NEAR(row(1), 0, 1e-9);
    EXPECT_GT(row(2), 1.0);
    const Image img = r.render_to_image();
    expect_rgb(pixel(img, W / 2, H / 2), kBoxColor, "lookat centre");
    expect_corners(img, kWhite);

    // setup_camera(camera()) reproduces the image (the box is off-centre, so a flip would show); at most
    // a few edge pixels may round differently.
    OffscreenRenderer again(W, H);
    again.add("box", box(), RenderMaterial(Shader::DefaultUnlit));
    again.setup_camera(cam);
    const auto a = img.to_bytes(), b = again.render_to_image().to_bytes();
    ASSERT_EQ(a.size(), b.size());
    int differ = 0;
    for (std::size_t i = 0; i < a.size(); i += 3)
        differ += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    EXPECT_LE(differ, 20);
}

TEST(Visualization, RenderToPngWritesTheImage) {
    OffscreenRenderer r = pinhole_renderer();
    r.add("box", box(), RenderMaterial(Shader::DefaultUnlit));
    const std::string path = o3dpp_test::tmp_path("visualization_box.png");
    r.render_to_png(path);
    const Image png = o3dpp::read_image(path);
    EXPECT_EQ(png.num_channels(), 3);
    EXPECT_EQ(png.to_bytes(), r.render_to_image().to_bytes());
    std::remove(path.c_str());
    EXPECT_O3D_ERROR(r.render_to_png("/nonexistent/dir/box.png"), O3D_ERROR_IO);
}

TEST(Visualization, BadArgumentsThrow) {
    EXPECT_O3D_ERROR(OffscreenRenderer(0, 10), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(OffscreenRenderer(10, 10, static_cast<RenderBackend>(7)), O3D_ERROR_INVALID_ARGUMENT);
    OffscreenRenderer r(W, H);
    EXPECT_O3D_ERROR(r.setup_camera(PinholeIntrinsic(W + 1, H, 100, 100, 80, 60), o3dpp::identity4()),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(r.setup_camera(camera_k(), Mat4{2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(r.setup_camera_lookat({0, 0, 0}, {0, 0, 1}, {0, 0, 1}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(r.setup_camera_lookat({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 5.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(r.setup_camera(0.0, {0, 0, 1}, {0, 0, 0}, {0, 1, 0}), O3D_ERROR_INVALID_ARGUMENT);
    RenderOption o;
    o.point_size = 100;
    EXPECT_O3D_ERROR(r.set_render_option(o), O3D_ERROR_INVALID_ARGUMENT);
}
