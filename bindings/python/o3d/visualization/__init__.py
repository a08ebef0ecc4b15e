"""o3d.visualization: RenderOption and its enums (MeshShadeOption, PointColorOption, MeshColorOption), and
:mod:`o3d.visualization.rendering`, the offscreen renderer (OffscreenRenderer, MaterialRecord).

Rendering needs no display: the renderer's OpenGL context comes from EGL (Mesa's surfaceless platform,
software rendering where there is no GPU), else from a hidden GLFW window. There is no on-screen viewer
(no draw_geometries / Visualizer yet): render to an image or a PNG file instead.
"""
from .._o3d import (  # noqa: F401
    MeshColorOption,
    MeshShadeOption,
    PointColorOption,
    RenderOption,
)
from . import rendering  # noqa: E402,F401

__all__ = ["RenderOption", "MeshShadeOption", "PointColorOption", "MeshColorOption", "rendering"]
