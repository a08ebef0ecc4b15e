"""Open3D's draw_geometries family. With a display ($DISPLAY) each opens a Visualizer window and runs it until
it is closed. Without one, draw_geometries shows o3d's offscreen render inline in a Jupyter notebook, and
everything else raises UnsupportedError saying what to use instead (a hidden Visualizer window or
rendering.OffscreenRenderer, neither of which needs a display).
"""
import contextlib
import os

from .. import _o3d
from .. import io as _io
from . import rendering


def render_geometries_png(geometry_list, width=1920, height=1080, point_show_normal=False,
                          mesh_show_wireframe=False, mesh_show_back_face=False, lookat=None, up=None, front=None,
                          zoom=None):
    """The PNG bytes of `geometry_list` drawn as draw_geometries would draw them (o3d extra)."""
    renderer = rendering.OffscreenRenderer(int(width), int(height))
    option = renderer.render_option
    option.point_show_normal = bool(point_show_normal)
    option.mesh_show_wireframe = bool(mesh_show_wireframe)
    option.mesh_show_back_face = bool(mesh_show_back_face)
    for i, geometry in enumerate(geometry_list):
        renderer.scene.add_geometry(f"geometry_{i}", geometry)
    if any(v is not None for v in (lookat, up, front, zoom)):
        # Open3D's ViewControl keeps its defaults for the values not given.
        renderer.setup_camera_lookat(lookat if lookat is not None else _scene_center(geometry_list),
                                     front if front is not None else [0, 0, 1],
                                     up if up is not None else [0, 1, 0], 0.7 if zoom is None else zoom)
    return _io.write_image_to_bytes(renderer.render_to_image(), "png")


def _scene_center(geometry_list):
    import numpy as np
    lows, highs = [], []
    for g in geometry_list:
        if hasattr(g, "get_min_bound"):
            lows.append(np.asarray(g.get_min_bound()))
            highs.append(np.asarray(g.get_max_bound()))
    if not lows:
        return [0.0, 0.0, 0.0]
    return (np.min(lows, axis=0) + np.max(highs, axis=0)) / 2


def _notebook_display():
    """IPython's display function when running in a Jupyter kernel, else None."""
    try:
        from IPython import get_ipython
        from IPython.display import Image, display
    except ImportError:
        return None
    shell = get_ipython()
    if shell is None or "IPKernelApp" not in getattr(shell, "config", {}):
        return None
    return lambda png: display(Image(data=png))


def _no_display():
    return _o3d.UnsupportedError(
        "no display to open a window on ($DISPLAY is not set); use a hidden window "
        "(o3d.visualization.Visualizer().create_window(visible=False), with capture_screen_image) or "
        "o3d.visualization.rendering.OffscreenRenderer (render_to_image / render_to_png); in a Jupyter notebook "
        "draw_geometries renders inline")


@contextlib.contextmanager
def _window(cls, geometry_list, window_name, width, height, left, top):
    """A visible `cls` window showing geometry_list, destroyed on leaving."""
    if not os.environ.get("DISPLAY"):
        raise _no_display()
    vis = cls()
    vis.create_window(window_name, width, height, left, top)
    try:
        for geometry in geometry_list:
            vis.add_geometry(geometry)
        yield vis
    finally:
        vis.destroy_window()


def draw_geometries(geometry_list, window_name="Open3D", width=1920, height=1080, left=50, top=50,
                    point_show_normal=False, mesh_show_wireframe=False, mesh_show_back_face=False,
                    lookat=None, up=None, front=None, zoom=None):
    """Open3D's draw_geometries: a window until it is closed. Without a display, in a Jupyter notebook: the
    offscreen render of the same view, shown inline; elsewhere: raises UnsupportedError."""
    if os.environ.get("DISPLAY"):
        with _window(_o3d.Visualizer, geometry_list, window_name, width, height, left, top) as vis:
            option = vis.get_render_option()
            option.point_show_normal = bool(point_show_normal)
            option.mesh_show_wireframe = bool(mesh_show_wireframe)
            option.mesh_show_back_face = bool(mesh_show_back_face)
            vis.get_view_control().set_view(front=front, lookat=lookat, up=up, zoom=zoom)
            vis.run()
        return
    show = _notebook_display()
    if show is None:
        raise _no_display()
    show(render_geometries_png(geometry_list, width, height, point_show_normal, mesh_show_wireframe,
                               mesh_show_back_face, lookat, up, front, zoom))


def draw_geometries_with_animation_callback(geometry_list, callback_function, window_name="Open3D", width=1920,
                                            height=1080, left=50, top=50):
    """A window calling callback_function(vis) -> bool (redraw) every frame, until it is closed."""
    with _window(_o3d.Visualizer, geometry_list, window_name, width, height, left, top) as vis:
        vis.register_animation_callback(callback_function)
        vis.run()


def draw_geometries_with_key_callbacks(geometry_list, key_to_callback, window_name="Open3D", width=1920,
                                       height=1080, left=50, top=50):
    """A window with key_to_callback: {key (GLFW number, ord('K')): callback(vis) -> bool}."""
    with _window(_o3d.VisualizerWithKeyCallback, geometry_list, window_name, width, height, left, top) as vis:
        for key, callback in key_to_callback.items():
            vis.register_key_callback(key, callback)
        vis.run()


def draw_geometries_with_custom_animation(geometry_list, window_name="Open3D", width=1920, height=1080, left=50,
                                          top=50, optional_view_trajectory_json_file="", capture_dir=None,
                                          capture_depth=False):
    """A window that first plays optional_view_trajectory_json_file (a ViewTrajectory JSON) once, then stays
    until closed. o3d extras: capture_dir writes image_%06d.png of each played frame (and depth_%06d.png, 16-bit
    millimetres, with capture_depth)."""
    with _window(_o3d.Visualizer, geometry_list, window_name, width, height, left, top) as vis:
        if optional_view_trajectory_json_file:
            vis.play_view_trajectory(optional_view_trajectory_json_file, capture_dir, capture_depth)
        vis.run()


def draw_geometries_with_editing(geometry_list, window_name="Open3D", width=1920, height=1080, left=50, top=50):
    """A VisualizerWithEditing window (Shift + left click picks a point of the first geometry, Shift + right
    click drops the last pick). Returns the picked vertex indices (an o3d addition: Open3D returns None)."""
    with _window(_o3d.VisualizerWithEditing, geometry_list, window_name, width, height, left, top) as vis:
        vis.run()
        return vis.get_picked_points()
