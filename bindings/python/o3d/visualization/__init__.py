"""o3d.visualization: RenderOption and its enums (MeshShadeOption, PointColorOption, MeshColorOption), and
:mod:`o3d.visualization.rendering`, the offscreen renderer (OffscreenRenderer, MaterialRecord).

Rendering needs no display: the renderer's OpenGL context comes from EGL (Mesa's surfaceless platform,
software rendering where there is no GPU), else from a hidden GLFW window. There is no on-screen viewer
yet (no Visualizer): render to an image or a PNG file instead. ``draw_geometries`` works in a Jupyter
notebook, where it shows the offscreen render inline; elsewhere it raises UnsupportedError.
"""
from .._o3d import (  # noqa: F401
    MeshColorOption,
    MeshShadeOption,
    PointColorOption,
    RenderOption,
)
from . import rendering  # noqa: E402,F401
from ._draw import draw_geometries, render_geometries_png  # noqa: E402,F401

__all__ = ["RenderOption", "MeshShadeOption", "PointColorOption", "MeshColorOption", "rendering",
           "draw_geometries", "render_geometries_png"]
