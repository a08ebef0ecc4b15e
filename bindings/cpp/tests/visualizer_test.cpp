// SPDX-License-Identifier: MIT
// Visualizer through the wrapper: a hidden 160 x 120 window (EGL, no display needed) showing a unit cube
// centred at the origin, lights off so that its pixels have exactly its colour. Checked against Open3D's
// ViewControl model (depth at the centre), by the effect of keys and callbacks on the render option, the
// view and the captured image, exceptions thrown by callbacks, and the error paths.
#include <cmath>
#include <stdexcept>

#include "test_util.hpp"

using o3dpp::KeyAction;
using o3dpp::MouseButton;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;
using o3dpp::View;
using o3dpp::Visualizer;

namespace {

constexpr int W = 160, H = 120;

Visualizer window(const Vec3& color) {
    Visualizer vis;
    vis.create_window("test", W, H, -1, -1, false);
    TriangleMesh cube = TriangleMesh::create_box(1, 1, 1);
    cube.translate({-0.5, -0.5, -0.5});
    cube.paint_uniform_color(color);
    vis.add("cube", cube);
    o3dpp::RenderOption option = vis.render_option();
    option.light_on = false;
    vis.set_render_option(option);
    return vis;  // moved: its callbacks' state follows it
}

std::vector<float> screen(Visualizer& vis) { return vis.capture_screen_float_buffer().to_values<float>(); }

Vec3 rgb_at(Visualizer& vis, int u, int v) {
    const auto f = screen(vis);
    const std::size_t i = (static_cast<std::size_t>(v) * W + u) * 3;
    return {f[i], f[i + 1], f[i + 2]};
}

int background_pixels(Visualizer& vis) {
    const auto f = screen(vis);
    int n = 0;
    for (std::size_t i = 0; i < f.size(); i += 3) n += f[i] == 1.0f && f[i + 1] == 1.0f && f[i + 2] == 1.0f;
    return n;
}

TEST(Visualizer, DefaultViewMatchesTheViewControlModel) {
    Visualizer vis = window({1, 0, 0});
    EXPECT_EQ(rgb_at(vis, 0, 0), (Vec3{1, 1, 1}));
    EXPECT_EQ(rgb_at(vis, W / 2, H / 2), (Vec3{1, 0, 0}));
    // Eye on +z at zoom * extent / tan(30 deg) from the centre; the front face is 0.5 nearer.
    const auto depth = vis.capture_depth_float_buffer().to_values<float>();
    const double expected = 0.7 / std::tan(M_PI / 6) - 0.5;
    EXPECT_NEAR(depth[(H / 2) * W + W / 2], expected, 1e-3 * expected);
    EXPECT_EQ(vis.field_of_view(), 60.0);
    const View view = vis.view();
    EXPECT_EQ(view.front, (Vec3{0, 0, 1}));
    EXPECT_EQ(view.zoom, 0.7);
    EXPECT_TRUE(vis.has("cube"));
    EXPECT_FALSE(vis.has("other"));
}

TEST(Visualizer, BuiltinKeysByTheirEffect) {
    Visualizer vis = window({1, 0, 0});
    vis.send_key('=', KeyAction::Press);
    EXPECT_EQ(vis.render_option().point_size, 6.0);
    const int default_view = background_pixels(vis);
    vis.send_key('[', KeyAction::Press);
    EXPECT_EQ(vis.field_of_view(), 55.0);
    EXPECT_NE(background_pixels(vis), default_view);
    vis.send_key('R', KeyAction::Press);
    EXPECT_EQ(background_pixels(vis), default_view);
    EXPECT_TRUE(vis.poll_events());
    vis.send_key('Q', KeyAction::Press);
    EXPECT_FALSE(vis.poll_events());
}

// Captures read the frame already drawn when nothing changed (no second draw), so every change must show.
TEST(Visualizer, CapturesFollowEveryChange) {
    Visualizer vis = window({1, 0, 0});
    const int front_view = background_pixels(vis);
    EXPECT_EQ(background_pixels(vis), front_view);
    vis.rotate(150, 0);  // the cube turned by 26 degrees about the vertical
    const int turned = background_pixels(vis);
    EXPECT_NE(turned, front_view);
    TriangleMesh cube = TriangleMesh::create_box(1, 1, 1);
    cube.translate({-0.5, -0.5, -0.5});
    cube.paint_uniform_color({0, 1, 0});
    vis.add("cube", cube, false);  // an update under the same name, the view kept
    EXPECT_EQ(rgb_at(vis, W / 2, H / 2), (Vec3{0, 1, 0}));
    EXPECT_EQ(background_pixels(vis), turned);
    const auto depth = vis.capture_depth_float_buffer().to_values<float>();
    EXPECT_GT(depth[(H / 2) * W + W / 2], 0.0f);  // the same frame's depth, read after its colour
    EXPECT_EQ(depth[0], 0.0f);
    vis.update_renderer();
    EXPECT_EQ(background_pixels(vis), turned);
}

TEST(Visualizer, KeyCallbacksChangeTheCapture) {
    Visualizer vis = window({1, 0, 0});
    int calls = 0;
    vis.register_key_callback('K', [&](Visualizer& v, KeyAction action, int mods) {
        ++calls;
        EXPECT_EQ(action, KeyAction::Press);
        EXPECT_EQ(mods, O3D_KEY_MOD_CONTROL);
        o3dpp::RenderOption option = v.render_option();
        option.background_color = {0, 0, 0};
        v.set_render_option(option);
        return true;
    });
    vis.send_key('K', KeyAction::Release);
    EXPECT_EQ(calls, 0);
    vis.send_key('K', KeyAction::Press, O3D_KEY_MOD_CONTROL);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(rgb_at(vis, 0, 0), (Vec3{0, 0, 0}));
    std::vector<KeyAction> actions;
    vis.register_key_action_callback('=', [&](Visualizer&, KeyAction action, int) {
        actions.push_back(action);
        return false;
    });
    vis.send_key('=', KeyAction::Press).send_key('=', KeyAction::Release);
    EXPECT_EQ(actions, (std::vector<KeyAction>{KeyAction::Press, KeyAction::Release}));
    EXPECT_EQ(vis.render_option().point_size, 5.0);  // the binding no longer runs
}

TEST(Visualizer, AnimationCallbackRotatesTheViewThenCloses) {
    Visualizer vis = window({0, 0, 1});
    const int still = background_pixels(vis);
    int frames = 0;
    vis.register_animation_callback([&](Visualizer& v) {
        v.rotate(10, 0);
        if (++frames == 5) v.close();
        return true;
    });
    Visualizer moved = std::move(vis);  // the callback reaches the new owner
    moved.run();
    EXPECT_EQ(frames, 5);
    const Vec3 front = moved.view().front;  // five turns of 10 px = 0.15 rad about up
    EXPECT_NEAR(front[0], -std::sin(0.15), 1e-9);
    EXPECT_NEAR(front[1], 0.0, 1e-9);
    EXPECT_NEAR(front[2], std::cos(0.15), 1e-9);
    EXPECT_NE(background_pixels(moved), still);
}

TEST(Visualizer, CallbackExceptionsAreRethrownFromRunAndSend) {
    Visualizer vis = window({0, 1, 0});
    struct Spin : std::runtime_error {
        using std::runtime_error::runtime_error;
    };
    vis.register_animation_callback([](Visualizer&) -> bool { throw Spin("spin failed on purpose"); });
    try {
        vis.run();
        FAIL() << "run() did not throw";
    } catch (const Spin& e) {
        EXPECT_STREQ(e.what(), "spin failed on purpose");  // the original exception, not an o3dpp::Error
    }
    vis.register_key_callback('K', [](Visualizer&, KeyAction, int) -> bool { throw std::logic_error("key"); });
    EXPECT_THROW(vis.send_key('K', KeyAction::Press), std::logic_error);
    // A callback replacing itself while it runs: the old one lives until it returns.
    int calls = 0;
    vis.register_key_callback('J', [&](Visualizer& v, KeyAction, int) {
        v.register_key_callback('J', [&](Visualizer&, KeyAction, int) { return calls += 10, false; });
        return ++calls, false;
    });
    vis.send_key('J', KeyAction::Press).send_key('J', KeyAction::Press);
    EXPECT_EQ(calls, 11);
    vis.register_animation_callback([](Visualizer& v) { return v.close(), false; });
    vis.run();  // still works afterwards
}

TEST(Visualizer, PinholeRoundTripGivesTheSameCapture) {
    Visualizer vis = window({0, 1, 0});
    vis.rotate(120, -40).change_field_of_view(-2);  // 50 degrees
    const o3dpp::PinholeCameraParameters camera = vis.to_pinhole();
    EXPECT_NEAR(camera.intrinsic.fy, H / (2 * std::tan(25 * M_PI / 180)), 1e-9);
    const auto before = screen(vis);
    vis.reset_view();
    EXPECT_NE(screen(vis), before);
    vis.from_pinhole(camera);
    EXPECT_EQ(screen(vis), before);
    o3dpp::PinholeCameraParameters off = camera;
    off.intrinsic.cx += 3;
    EXPECT_THROW(vis.from_pinhole(off), o3dpp::Error);
}

TEST(Visualizer, ViewStatusSetViewMouseAndPicking) {
    Visualizer vis = window({1, 0, 0});
    vis.rotate(50, 20);
    const std::string status = vis.view_status();
    const View turned = vis.view();
    EXPECT_NE(status.find("\"class_name\": \"ViewTrajectory\""), std::string::npos);
    vis.reset_view().set_view_status(status);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(vis.view().front[i], turned.front[i], 1e-9);
    const View side{{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, 0.5};
    vis.set_view(side);
    EXPECT_EQ(vis.view().front, side.front);
    EXPECT_EQ(vis.view().zoom, 0.5);
    vis.reset_view().send_mouse_move(10, 10).send_mouse_button(MouseButton::Left, KeyAction::Press);
    vis.send_mouse_move(110, 10).send_mouse_button(MouseButton::Left, KeyAction::Release).send_scroll(0, 5);
    EXPECT_NEAR(vis.view().front[0], -std::sin(0.3), 1e-9);  // 100 px at 0.003 rad a pixel
    EXPECT_NEAR(vis.view().zoom, 0.8, 1e-12);
    // Editing: Shift + click on a point picks it.
    Visualizer edit(true);
    edit.create_window("edit", W, H, -1, -1, false);
    const std::vector<Vec3> points{{-0.5, 0, 0}, {0, 0.3, 0}, {0.5, -0.2, 0.1}};
    edit.add("cloud", o3dpp::PointCloud(points));
    const auto cam = edit.to_pinhole();
    const auto& e = cam.extrinsic;
    const Vec3& p = points[2];
    double c[3];
    for (int r = 0; r < 3; ++r) c[r] = e[4 * r] * p[0] + e[4 * r + 1] * p[1] + e[4 * r + 2] * p[2] + e[4 * r + 3];
    const o3dpp::PinholeIntrinsic& k = cam.intrinsic;
    edit.send_mouse_move(k.fx * c[0] / c[2] + k.cx + 1, k.fy * c[1] / c[2] + k.cy);
    edit.send_mouse_button(MouseButton::Left, KeyAction::Press, O3D_KEY_MOD_SHIFT);
    edit.send_mouse_button(MouseButton::Left, KeyAction::Release, O3D_KEY_MOD_SHIFT);
    EXPECT_EQ(edit.picked_points(), (std::vector<int32_t>{2}));
}

TEST(Visualizer, ImagesAreShownFlatAndScaledToFit) {
    Visualizer vis;
    vis.create_window("image", W, H, -1, -1, false);
    std::vector<uint8_t> green;
    for (int i = 0; i < 8 * 8; ++i) green.insert(green.end(), {0, 255, 0});
    vis.add("photo", o3dpp::Image::from_values<uint8_t>(8, 8, green, 3));
    EXPECT_TRUE(vis.has("photo"));
    // 8 x 8 scaled to the window's height and centred: columns 20..139 of 160.
    EXPECT_EQ(rgb_at(vis, W / 2, H / 2), (Vec3{0, 1, 0}));
    EXPECT_EQ(rgb_at(vis, 25, 5), (Vec3{0, 1, 0}));
    EXPECT_EQ(rgb_at(vis, 5, H / 2), (Vec3{1, 1, 1}));
}

TEST(Visualizer, ErrorsThrowAndLeaveItUsable) {
    Visualizer vis;
    EXPECT_THROW(vis.run(), o3dpp::Error);  // no window
    EXPECT_THROW(vis.rotate(1, 1), o3dpp::Error);
    EXPECT_THROW(vis.capture_screen_float_buffer(), o3dpp::Error);
    EXPECT_THROW(vis.create_window("x", 0, 10, -1, -1, false), o3dpp::Error);
    vis.create_window("x", W, H, -1, -1, false);
    EXPECT_THROW(vis.create_window("x", W, H, -1, -1, false), o3dpp::Error);
    EXPECT_THROW(vis.remove("absent"), o3dpp::Error);
    EXPECT_THROW(vis.set_view(View{{0, 1, 0}, {0, 0, 0}, {0, 1, 0}, 0.7}), o3dpp::Error);  // front = up
    try {
        vis.set_view_status("{\"class_name\": \"RenderOption\"}");
        FAIL() << "set_view_status did not throw";
    } catch (const o3dpp::Error& e) {
        EXPECT_EQ(e.code(), O3D_ERROR_PARSE);
    }
    EXPECT_THROW(vis.play_view_trajectory("/nonexistent/t.json"), o3dpp::Error);
    vis.run();  // a hidden window without an animation callback: one frame
}

}  // namespace
