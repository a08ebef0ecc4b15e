"""draw_geometries without a display: inline in a notebook (its render is the offscreen renderer's with
draw_geometries' arguments), an UnsupportedError elsewhere. (With a display it opens a Visualizer window:
test_visualizer.py.)"""
import numpy as np
import pytest

import o3d
from o3d.visualization import _draw


def _cube():
    mesh = o3d.geometry.TriangleMesh.create_box(1.0, 1.0, 1.0)
    mesh.paint_uniform_color([0.2, 0.4, 0.8])
    mesh.compute_vertex_normals()
    return mesh


@pytest.fixture(autouse=True)
def no_display(monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)


def test_outside_a_notebook_it_raises_and_says_what_to_use(monkeypatch):
    monkeypatch.setattr(_draw, "_notebook_display", lambda: None)
    with pytest.raises(o3d.UnsupportedError, match="OffscreenRenderer"):
        o3d.visualization.draw_geometries([_cube()])


def test_in_a_notebook_it_shows_the_offscreen_render(monkeypatch):
    shown = []
    monkeypatch.setattr(_draw, "_notebook_display", lambda: shown.append)
    view = dict(lookat=[0.5, 0.5, 0.5], front=[0.3, -0.4, 1.0], up=[0, 1, 0], zoom=0.9)
    o3d.visualization.draw_geometries([_cube()], width=160, height=120, mesh_show_wireframe=True, **view)
    assert len(shown) == 1
    image = np.asarray(o3d.io.read_image_from_bytes(shown[0], "png"))
    assert image.shape == (120, 160, 3)

    # The same picture as the offscreen renderer given the same view and options.
    r = o3d.visualization.rendering.OffscreenRenderer(160, 120)
    r.render_option.mesh_show_wireframe = True
    r.scene.add_geometry("cube", _cube())
    r.setup_camera_lookat(view["lookat"], view["front"], view["up"], view["zoom"])
    assert np.array_equal(image, np.asarray(r.render_to_image()))
    # Something was drawn over the white background, and the wireframe left black pixels.
    assert (image != 255).any(axis=2).sum() > 500
    assert (image == 0).all(axis=2).sum() > 20


def test_missing_view_values_keep_view_control_defaults(monkeypatch):
    shown = []
    monkeypatch.setattr(_draw, "_notebook_display", lambda: shown.append)
    o3d.visualization.draw_geometries([_cube()], width=64, height=48, zoom=0.5)
    # lookat defaults to the scene's centre, front +z, up +y: the cube's centre is drawn at the image centre.
    image = np.asarray(o3d.io.read_image_from_bytes(shown[0], "png"))
    assert tuple(image[24, 32]) != (255, 255, 255)
