"""o3d.visualization.rendering: OffscreenRenderer (with its Open3DScene, ``renderer.scene``) and
MaterialRecord, under Open3D's names.

Example::

    renderer = o3d.visualization.rendering.OffscreenRenderer(640, 480)
    material = o3d.visualization.rendering.MaterialRecord()
    material.shader = "defaultUnlit"
    renderer.scene.add_geometry("mesh", mesh, material)
    renderer.scene.set_background([0, 0, 0, 1])
    renderer.setup_camera(60.0, [0, 0, 0], [0, 0, 3], [0, 1, 0])
    image = renderer.render_to_image()  # o3d.geometry.Image, RGB uint8

o3d extras: ``OffscreenRenderer(w, h, backend="egl")``, ``setup_camera_lookat(lookat, front, up, zoom)``,
``get_camera()``, ``render_to_png(path)``, ``render_option`` (a live RenderOption), ``backend``, ``size``.
"""
from .._o3d import (  # noqa: F401
    MaterialRecord,
    OffscreenRenderer,
    Open3DScene,
)

__all__ = ["OffscreenRenderer", "Open3DScene", "MaterialRecord"]
