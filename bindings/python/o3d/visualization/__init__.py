"""o3d.visualization: RenderOption and its enums (MeshShadeOption, PointColorOption, MeshColorOption), and
:mod:`o3d.visualization.rendering`, the offscreen renderer (OffscreenRenderer, MaterialRecord).

Rendering needs no display: the renderer's OpenGL context comes from EGL (Mesa's surfaceless platform,
software rendering where there is no GPU), else from a hidden GLFW window.

The viewer (Visualizer, its variants, ViewControl, the draw_geometries family): a visible window needs a
display ($DISPLAY; Xvfb will do), a hidden one (``create_window(visible=False)``) renders through EGL.
o3d extras: Visualizer.send_* (scripted input) and play_view_trajectory, ViewControl.set_view and
get/set_view_status. Where Open3D returns False on failure, o3d raises.
"""
from .._o3d import (  # noqa: F401
    MeshColorOption,
    MeshShadeOption,
    PointColorOption,
    RenderOption,
)
from .._o3d import ViewControl, Visualizer, VisualizerWithEditing, VisualizerWithKeyCallback  # noqa: F401
from .._o3d import SelectionPolygonVolume, read_selection_polygon_volume  # noqa: F401
from . import rendering  # noqa: E402,F401
from ._draw import (draw_geometries, draw_geometries_with_animation_callback,  # noqa: E402,F401
                    draw_geometries_with_custom_animation, draw_geometries_with_editing,
                    draw_geometries_with_key_callbacks, render_geometries_png)

__all__ = ["RenderOption", "MeshShadeOption", "PointColorOption", "MeshColorOption", "rendering",
           "draw_geometries", "render_geometries_png", "Visualizer", "VisualizerWithKeyCallback",
           "VisualizerWithEditing", "ViewControl", "draw_geometries_with_animation_callback",
           "draw_geometries_with_key_callbacks", "draw_geometries_with_custom_animation",
           "draw_geometries_with_editing", "SelectionPolygonVolume", "read_selection_polygon_volume"]
