"""o3d.visualization.Visualizer and friends driven from code, with nobody at the keyboard. Hidden windows render
through EGL, so these run headless; the visible-window tests run when $DISPLAY is set (Xvfb will do) and
otherwise check the clear error. Results are checked against Open3D's ViewControl model (depth at the centre),
by key bindings' effects, and by comparing captured pictures."""
import json
import math
import os
import pathlib
import subprocess
import sys
import threading

import numpy as np
import pytest

import o3d

W, H = 160, 120
vis_module = o3d.visualization
EXAMPLES = pathlib.Path(__file__).resolve().parents[3] / "examples" / "python"


def _window(cls=vis_module.Visualizer, **kwargs):
    vis = cls(**kwargs)
    assert vis.create_window("test", W, H, visible=False) is True
    return vis


def _cube(rgb):
    mesh = o3d.geometry.TriangleMesh.create_box(1.0, 1.0, 1.0)
    mesh.translate([-0.5, -0.5, -0.5])
    mesh.paint_uniform_color(rgb)
    return mesh


def _add_cube(vis, rgb):
    """A unit cube at the origin with lights off, so that its pixels have exactly its colour."""
    mesh = _cube(rgb)
    assert vis.add_geometry(mesh) is True
    vis.get_render_option().light_on = False
    return mesh


def _screen(vis):
    image = np.asarray(vis.capture_screen_float_buffer(True))
    assert image.shape == (H, W, 3) and image.dtype == np.float32
    return image


def _background(vis):
    return int((_screen(vis) == 1.0).all(axis=2).sum())


def _front(view):
    front = view.get_front()
    # get_view_status (Open3D's Ctrl+C JSON) says the same.
    np.testing.assert_array_equal(json.loads(view.get_view_status())["trajectory"][0]["front"], front)
    return front


def test_default_view_matches_the_viewcontrol_model(tmp_path):
    vis = _window()
    _add_cube(vis, [1, 0, 0])
    image = _screen(vis)
    for corner in (image[0, 0], image[0, -1], image[-1, 0], image[-1, -1]):
        assert tuple(corner) == (1, 1, 1)
    assert tuple(image[H // 2, W // 2]) == (1, 0, 0)
    # Open3D's default view: the eye on +z, zoom * extent / tan(30 deg) from the box centre; the front face
    # (z = 0.5) is that minus 0.5 away.
    expected = 0.7 / math.tan(math.radians(30)) - 0.5
    depth = np.asarray(vis.capture_depth_float_buffer())
    assert depth[H // 2, W // 2] == pytest.approx(expected, rel=1e-3)
    assert depth[0, 0] == 0
    assert vis.get_view_control().get_field_of_view() == 60
    vis.capture_depth_image(str(tmp_path / "depth.png"))
    assert np.asarray(o3d.io.read_image(str(tmp_path / "depth.png")))[H // 2, W // 2] == round(expected * 1000)
    vis.capture_screen_image(str(tmp_path / "screen.png"), do_render=True)
    assert tuple(np.asarray(o3d.io.read_image(str(tmp_path / "screen.png")))[H // 2, W // 2]) == (255, 0, 0)
    assert vis.get_window_name() == "test"
    with pytest.raises(o3d.O3DIOError):
        vis.capture_screen_image(str(tmp_path / "missing" / "x.png"))
    vis.destroy_window()


def test_key_bindings_by_their_effect():
    vis = _window()
    _add_cube(vis, [1, 0, 0])
    option, view = vis.get_render_option(), vis.get_view_control()
    size = option.point_size
    vis.send_key_event(ord("="))
    assert option.point_size == size + 1
    default_view = _background(vis)
    vis.send_key_event(ord("["))
    assert view.get_field_of_view() == 55
    assert _background(vis) != default_view  # same apparent size, another perspective
    view.rotate(200, 0)
    vis.send_key_event(ord("R"))
    assert view.get_field_of_view() == 60
    np.testing.assert_allclose(_front(view), [0, 0, 1], atol=1e-12)
    assert _background(vis) == default_view
    with pytest.raises(o3d.InvalidArgumentError):
        vis.send_key_event(ord("W"), action=7)


def test_key_callback_changes_the_background():
    vis = _window(vis_module.VisualizerWithKeyCallback)
    _add_cube(vis, [1, 0, 0])
    calls = []

    def paint_black(v):
        calls.append(v)
        v.get_render_option().background_color = [0, 0, 0]
        return True

    vis.register_key_callback(ord("K"), paint_black)
    vis.send_key_event(ord("K"), action=0)  # a key callback runs on press and repeat only
    assert calls == []
    vis.send_key_event(ord("K"))
    assert len(calls) == 1 and calls[0] is vis
    assert tuple(_screen(vis)[0, 0]) == (0, 0, 0)
    assert tuple(_screen(vis)[H // 2, W // 2]) == (1, 0, 0)
    # An action callback replaces the '=' binding and sees release and the modifiers too.
    actions = []
    size = vis.get_render_option().point_size
    vis.register_key_action_callback(ord("="), lambda v, action, mods: actions.append((action, mods)))
    vis.send_key_event(ord("="), 0, 1)
    assert actions == [(0, 1)]
    assert vis.get_render_option().point_size == size
    with pytest.raises(TypeError):
        vis.register_key_callback(ord("K"), 3)


def test_animation_callback_rotates_the_view_then_closes():
    vis = _window()
    _add_cube(vis, [0, 0, 1])
    still = _background(vis)
    frames = []

    def spin(v):
        v.get_view_control().rotate(10, 0)
        frames.append(1)
        if len(frames) == 5:
            v.close()
        return True

    vis.register_animation_callback(spin)
    vis.run()
    assert len(frames) == 5
    # Five turns of 10 px (0.003 rad a pixel) about the up axis.
    np.testing.assert_allclose(_front(vis.get_view_control()), [-math.sin(0.15), 0, math.cos(0.15)], atol=1e-9)
    assert _background(vis) != still


class Boom(Exception):
    pass


def test_an_exception_in_a_callback_comes_out_of_run():
    vis = _window(vis_module.VisualizerWithKeyCallback)
    _add_cube(vis, [1, 0, 0])
    raised = Boom("on purpose")

    def fail(v):
        raise raised

    vis.register_animation_callback(fail)
    with pytest.raises(Boom) as info:
        vis.run()
    assert info.value is raised
    vis.register_key_callback(ord("K"), fail)
    with pytest.raises(Boom):
        vis.send_key_event(ord("K"))
    # The visualizer still works: without an animation callback a hidden window draws once and run returns.
    vis.register_animation_callback(None)
    vis.run()
    assert tuple(_screen(vis)[H // 2, W // 2]) == (1, 0, 0)


def test_pinhole_round_trip_reproduces_the_image():
    vis = _window()
    _add_cube(vis, [0, 1, 0])
    view = vis.get_view_control()
    view.rotate(120, -40)
    view.change_field_of_view(-2)  # 50 degrees
    params = view.convert_to_pinhole_camera_parameters()
    assert (params.intrinsic.width, params.intrinsic.height) == (W, H)
    assert params.intrinsic.intrinsic_matrix[1, 1] == pytest.approx(H / (2 * math.tan(math.radians(25))))
    before = _screen(vis)
    vis.reset_view_point(True)
    assert not np.array_equal(_screen(vis), before)
    assert view.convert_from_pinhole_camera_parameters(params) is True
    np.testing.assert_array_equal(_screen(vis), before)
    # A camera the view cannot take raises and leaves the view as it was.
    k = params.intrinsic.intrinsic_matrix
    wide = o3d.camera.PinholeCameraParameters()
    wide.intrinsic = o3d.camera.PinholeCameraIntrinsic(2 * W, H, k[0, 0], k[1, 1], W - 0.5, k[1, 2])
    wide.extrinsic = params.extrinsic
    with pytest.raises(o3d.InvalidArgumentError):
        view.convert_from_pinhole_camera_parameters(wide)
    np.testing.assert_array_equal(_screen(vis), before)


POINTS = np.array([[-0.5, 0, 0], [0, 0.3, 0], [0.5, -0.2, 0.1]])


def _shift_click(vis, point):
    """Shift + left click on the pixel where `point` is drawn."""
    params = vis.get_view_control().convert_to_pinhole_camera_parameters()
    k, e = params.intrinsic.intrinsic_matrix, params.extrinsic
    x, y, z = (e @ np.append(point, 1.0))[:3]
    vis.send_mouse_move(k[0, 0] * x / z + k[0, 2] + 1, k[1, 1] * y / z + k[1, 2])
    vis.send_mouse_button(0, 1, 1)
    vis.send_mouse_button(0, 0, 1)


def test_editing_picks_the_clicked_points():
    vis = vis_module.VisualizerWithEditing(voxel_size=-1.0, use_dialog=True, directory="")
    vis.create_window("pick", W, H, visible=False)
    vis.add_geometry(o3d.geometry.PointCloud(o3d.utility.Vector3dVector(POINTS)))
    _shift_click(vis, POINTS[2])
    _shift_click(vis, POINTS[1])
    assert vis.get_picked_points() == [2, 1]
    vis.send_mouse_button(1, 0, 1)  # Shift + right click drops the last pick
    assert vis.get_picked_points() == [2]


def test_mouse_drag_and_scroll_move_the_view():
    vis = _window()
    _add_cube(vis, [1, 0, 0])
    vis.send_mouse_move(10, 10)
    vis.send_mouse_button(0, 1)
    vis.send_mouse_move(110, 10)
    vis.send_mouse_button(0, 0)
    view = vis.get_view_control()
    np.testing.assert_allclose(_front(view), [-math.sin(0.3), 0, math.cos(0.3)], atol=1e-9)
    vis.send_scroll(0, 5)
    assert view.get_zoom() == pytest.approx(0.8)
    np.testing.assert_allclose(view.get_lookat(), [0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(view.get_up(), [0, 1, 0], atol=1e-12)


def test_update_geometry_after_moving_points_changes_the_picture():
    vis = _window()
    rng = np.random.default_rng(3)
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(rng.uniform(-0.5, 0.5, (400, 3))))
    cloud.paint_uniform_color([0, 0, 0])
    vis.add_geometry(cloud)
    view = vis.get_view_control()
    status = view.get_view_status()

    def mean_column(image):
        return np.nonzero((image < 1).any(axis=2))[1].mean()

    before = _screen(vis)
    cloud.translate([0.3, 0, 0])
    assert vis.update_geometry(cloud) is True
    after = _screen(vis)
    assert view.get_view_status() == status  # the view was kept
    assert mean_column(after) > mean_column(before) + 5  # the points moved right on screen
    assert vis.has_geometry(cloud)
    assert vis.remove_geometry(cloud) is True
    assert not vis.has_geometry(cloud)
    assert _background(vis) == W * H
    with pytest.raises(o3d.InvalidArgumentError):
        vis.update_geometry(cloud)
    with pytest.raises(TypeError):
        vis.add_geometry("not a geometry")


def test_an_image_is_drawn_flat_scaled_to_fit():
    vis = _window()
    blue = np.zeros((30, 30, 3), np.uint8)
    blue[..., 2] = 255
    vis.add_geometry(o3d.geometry.Image(blue))
    image = _screen(vis)
    # A square image in a 4:3 window: scaled to the window's height, centred, white beside it.
    assert tuple(image[H // 2, W // 2]) == (0, 0, 1) and tuple(image[H // 2, 2]) == (1, 1, 1)
    assert (image == [0, 0, 1]).all(axis=2).sum() == pytest.approx(H * H, rel=0.05)


def test_render_option_is_live_and_view_values_are_checked():
    vis = _window()
    _add_cube(vis, [1, 0, 0])
    option = vis.get_render_option()
    option.background_color = [0, 0, 1]
    assert tuple(_screen(vis)[0, 0]) == (0, 0, 1)
    with pytest.raises(o3d.InvalidArgumentError):
        option.point_size = 1000
    view = vis.get_view_control()
    with pytest.raises(o3d.InvalidArgumentError):
        view.set_front([0, 1, 0])  # parallel to up
    view.set_view(front=[0, 1, 0], up=[0, 0, 1])  # together they are fine
    np.testing.assert_allclose(_front(view), [0, 1, 0], atol=1e-12)


def test_trajectory_playback_writes_captures(tmp_path):
    vis = _window()
    _add_cube(vis, [1, 0, 0])
    key = {"boundingbox_max": [0.5] * 3, "boundingbox_min": [-0.5] * 3, "field_of_view": 60.0, "lookat": [0, 0, 0],
           "up": [0, 1, 0], "zoom": 0.7}
    trajectory = {"class_name": "ViewTrajectory", "interval": 2, "is_loop": False,
                  "trajectory": [dict(key, front=[0, 0, 1]), dict(key, front=[1, 0, 0])]}
    path = tmp_path / "trajectory.json"
    path.write_text(json.dumps(trajectory))
    vis.play_view_trajectory(str(path), str(tmp_path), capture_depth=True)
    assert sorted(p.name for p in tmp_path.glob("*_0000*.png")) == [
        f"{kind}_{i:06d}.png" for kind in ("depth", "image") for i in range(4)]
    np.testing.assert_allclose(_front(vis.get_view_control()), [1, 0, 0], atol=1e-12)
    with pytest.raises(o3d.O3DIOError):
        vis.play_view_trajectory(str(tmp_path / "absent.json"))


def test_a_visualizer_belongs_to_its_window_thread():
    vis = _window()
    errors = []

    def elsewhere():
        try:
            vis.poll_events()
        except o3d.InvalidArgumentError as e:
            errors.append(str(e))

    thread = threading.Thread(target=elsewhere)
    thread.start()
    thread.join()
    assert errors and "thread" in errors[0]
    assert vis.poll_events() is True


def test_visible_window_or_the_clear_error():
    vis = vis_module.Visualizer()
    if not os.environ.get("DISPLAY"):
        with pytest.raises(o3d.UnsupportedError):
            vis.create_window("o3d", W, H, visible=True)
        return
    assert vis.create_window("o3d", W, H, 10, 10) is True
    _add_cube(vis, [1, 0, 0])
    assert tuple(_screen(vis)[H // 2, W // 2]) == (1, 0, 0)
    vis.destroy_window()


def test_draw_geometries_with_animation_callback():
    frames = []

    def spin(v):
        frames.append(_screen(v))
        v.get_view_control().rotate(10, 0)
        if len(frames) == 3:
            v.close()
        return True

    if not os.environ.get("DISPLAY"):
        with pytest.raises(o3d.UnsupportedError, match=r"\$DISPLAY"):
            vis_module.draw_geometries_with_animation_callback([_cube([1, 0, 0])], spin, width=W, height=H)
        assert frames == []
        return
    vis_module.draw_geometries_with_animation_callback([_cube([1, 0, 0])], spin, width=W, height=H)
    assert len(frames) == 3
    assert tuple(frames[0][0, 0]) == (1, 1, 1) and tuple(frames[0][H // 2, W // 2]) != (1, 1, 1)
    assert not np.array_equal(frames[0], frames[2])  # the view turned


def test_figure2_example_writes_rotating_frames(data_file, tmp_path):
    run = subprocess.run([sys.executable, str(EXAMPLES / "figure2.py"), data_file("open3d/Feature/cloud_bin_0.pcd"),
                          data_file("open3d/knot.ply"), "--frames", "3", "--out", str(tmp_path)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    frames = [pathlib.Path(line) for line in run.stdout.split() if line.endswith(".png")]
    assert len(frames) == 3 and all(f.is_file() for f in frames)
    images = [np.asarray(o3d.io.read_image(str(f))) for f in frames]
    assert (images[0] != 255).any(axis=2).sum() > 1000  # the cloud and the mesh are drawn
    assert not np.array_equal(images[0], images[2])  # the view rotates


@pytest.fixture
def stand_in_display(monkeypatch):
    """$DISPLAY set, the draw_* windows hidden, and run() replaced by the next function in the returned list
    (called with the visualizer): the draw_* functions' window path, headless."""
    create = vis_module.Visualizer.create_window
    monkeypatch.setenv("DISPLAY", ":o3d-test")
    monkeypatch.setattr(vis_module.Visualizer, "create_window",
                        lambda self, *a, **k: create(self, *a, **{**k, "visible": False}))
    runs = []
    monkeypatch.setattr(vis_module.Visualizer, "run", lambda self: runs.pop(0)(self))
    return runs


def test_draw_geometries_opens_a_window_with_its_arguments(stand_in_display):
    seen = []

    def look(vis):
        view = json.loads(vis.get_view_control().get_view_status())["trajectory"][0]
        seen.append((vis.get_window_name(), vis.get_render_option().mesh_show_wireframe, view, _screen(vis)))

    stand_in_display.append(look)
    vis_module.draw_geometries([_cube([0.2, 0.4, 0.8])], "cube", W, H, mesh_show_wireframe=True, front=[0, 0, 2],
                               lookat=[0.1, 0, 0], zoom=0.9)
    (name, wireframe, view, image), = seen
    assert name == "cube" and wireframe
    np.testing.assert_allclose(view["front"], [0, 0, 1], atol=1e-12)
    np.testing.assert_allclose(view["lookat"], [0.1, 0, 0], atol=1e-12)
    assert view["zoom"] == pytest.approx(0.9)
    assert (image < 1).any(axis=2).sum() > 500 and (image == 0).all(axis=2).sum() > 20  # the wireframe's black


def test_draw_geometries_with_key_callbacks_and_editing(stand_in_display):
    def press(vis):
        vis.send_key_event(ord("K"))
        assert tuple(_screen(vis)[0, 0]) == (0, 0, 0)

    def black(vis):
        vis.get_render_option().background_color = [0, 0, 0]
        return True

    stand_in_display.append(press)
    vis_module.draw_geometries_with_key_callbacks([_cube([1, 0, 0])], {ord("K"): black}, width=W, height=H)
    stand_in_display.append(lambda vis: _shift_click(vis, POINTS[1]))
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(POINTS))
    assert vis_module.draw_geometries_with_editing([cloud], width=W, height=H) == [1]
    assert stand_in_display == []


def test_draw_geometries_with_custom_animation_plays_the_trajectory(stand_in_display, tmp_path):
    vis = _window()
    _add_cube(vis, [1, 0, 0])
    vis.get_view_control().rotate(100, 0)
    path = tmp_path / "view.json"
    path.write_text(vis.get_view_control().get_view_status())  # a trajectory of one key view
    fronts = []
    stand_in_display.append(lambda v: fronts.append(_front(v.get_view_control())))
    vis_module.draw_geometries_with_custom_animation([_cube([1, 0, 0])], width=W, height=H,
                                                     optional_view_trajectory_json_file=str(path),
                                                     capture_dir=str(tmp_path))
    np.testing.assert_allclose(fronts[0], _front(vis.get_view_control()), atol=1e-9)  # run() after playback
    assert (tmp_path / "image_000000.png").is_file()
