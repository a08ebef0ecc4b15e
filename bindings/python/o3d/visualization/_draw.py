"""draw_geometries without a display: in a Jupyter notebook it shows o3d's offscreen render inline.

o3d has no on-screen viewer yet, so outside a notebook draw_geometries raises UnsupportedError and says what
to use instead (rendering.OffscreenRenderer); the render itself is draw_geometries' own arguments applied to
the offscreen renderer (its RenderOption flags, and lookat/front/up/zoom as ViewControl takes them).
"""
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


def draw_geometries(geometry_list, window_name="Open3D", width=1920, height=1080, left=50, top=50,
                    point_show_normal=False, mesh_show_wireframe=False, mesh_show_back_face=False,
                    lookat=None, up=None, front=None, zoom=None):
    """Open3D's draw_geometries. In a Jupyter notebook: the offscreen render, shown inline. Elsewhere: raises
    UnsupportedError (o3d has no on-screen viewer yet). window_name, left and top only matter for a window."""
    show = _notebook_display()
    if show is None:
        raise _o3d.UnsupportedError(
            "draw_geometries: o3d has no on-screen viewer yet; in a Jupyter notebook it renders inline, elsewhere "
            "use o3d.visualization.rendering.OffscreenRenderer (render_to_image / render_to_png)")
    show(render_geometries_png(geometry_list, width, height, point_show_normal, mesh_show_wireframe,
                               mesh_show_back_face, lookat, up, front, zoom))
