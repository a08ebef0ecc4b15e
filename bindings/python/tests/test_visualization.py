"""o3d.visualization: RenderOption (JSON included) and the offscreen renderer, checked against the pinhole
camera model: background colour, an object's colour at its projected centre, depth along the optical axis,
silhouette areas. Runs headless (EGL, no DISPLAY)."""
import json
import math
import time

import numpy as np
import pytest

import o3d
from test_gil import max_stall_during

rendering = o3d.visualization.rendering
W, H = 160, 120
F = 100.0
CX, CY = (W - 1) / 2.0, (H - 1) / 2.0  # the optical axis between the four middle pixels
EYE_DISTANCE = 3.0
# Camera on +z looking at the origin, y up in the world (camera frame: x right, y down, z forward).
EXTRINSIC = np.array([[1.0, 0, 0, 0], [0, -1.0, 0, 0], [0, 0, -1.0, EYE_DISTANCE], [0, 0, 0, 1.0]])


def intrinsic(width=W, height=H, f=F):
    return o3d.camera.PinholeCameraIntrinsic(width, height, f, f, (width - 1) / 2.0, (height - 1) / 2.0)


def project(point):
    """Pixel (row, column) of a world point under INTRINSIC / EXTRINSIC."""
    x, y, z = (EXTRINSIC @ np.append(point, 1.0))[:3]
    return int(round(F * y / z + CY)), int(round(F * x / z + CX))


def unlit(**fields):
    m = rendering.MaterialRecord()
    m.shader = "defaultUnlit"
    for k, v in fields.items():
        setattr(m, k, v)
    return m


def renderer_with_camera(background=(0.0, 0.0, 0.0, 1.0), f=F):
    r = rendering.OffscreenRenderer(W, H)
    r.scene.set_background(list(background))
    r.setup_camera(intrinsic(f=f), EXTRINSIC)
    return r


def centred_cube(color):
    cube = o3d.geometry.TriangleMesh.create_box(1.0, 1.0, 1.0)
    cube.translate([-0.5, -0.5, -0.5])
    cube.paint_uniform_color(color)
    return cube


def rgb(r):
    return np.asarray(r.render_to_image())


def to_u8(color):
    return np.round(np.asarray(color) * 255.0)


def assert_color(pixel, color, tol=1):
    assert np.abs(pixel.astype(float) - to_u8(color)).max() <= tol, (pixel, to_u8(color))


# ---------------------------------------------------------------- RenderOption


def test_render_option_defaults_are_open3d_s():
    opt = o3d.visualization.RenderOption()
    np.testing.assert_array_equal(opt.background_color, [1.0, 1.0, 1.0])
    assert opt.point_size == 5.0
    assert opt.line_width == 1.0
    assert opt.light_on is True
    assert not (opt.point_show_normal or opt.mesh_show_wireframe or opt.mesh_show_back_face)
    assert opt.mesh_shade_option == o3d.visualization.MeshShadeOption.FlatShade
    assert opt.point_color_option == o3d.visualization.PointColorOption.Default
    assert opt.mesh_color_option == o3d.visualization.MeshColorOption.Color
    np.testing.assert_allclose(opt.default_mesh_color, [0.7, 0.7, 0.7])


def test_enum_values_are_open3d_s():
    P = o3d.visualization.PointColorOption
    assert [int(P.Default), int(P.Color), int(P.XCoordinate), int(P.YCoordinate), int(P.ZCoordinate),
            int(P.Normal)] == [0, 1, 2, 3, 4, 9]
    assert int(o3d.visualization.MeshColorOption.Normal) == 9
    assert int(o3d.visualization.MeshShadeOption.SmoothShade) == 1


def test_load_from_json_reads_open3d_s_file(data_file):
    path = data_file("open3d/renderoption.json")
    with open(path) as f:
        expected = json.load(f)
    opt = o3d.visualization.RenderOption()
    # Start away from the file's values, so each assertion below depends on the file.
    opt.background_color = [0.1, 0.2, 0.3]
    opt.point_size = 2.0
    opt.light_on = False
    opt.point_color_option = o3d.visualization.PointColorOption.XCoordinate
    opt.mesh_color_option = o3d.visualization.MeshColorOption.Default
    opt.mesh_shade_option = o3d.visualization.MeshShadeOption.SmoothShade
    opt.mesh_show_back_face = True
    opt.default_mesh_color = [0.0, 0.0, 0.0]
    assert opt.load_from_json(path) is True
    assert opt.point_color_option == o3d.visualization.PointColorOption.Normal
    np.testing.assert_allclose(opt.background_color, expected["background_color"])
    assert opt.point_size == expected["point_size"]
    assert opt.light_on == expected["light_on"]
    assert int(opt.mesh_color_option) == expected["mesh_color_option"]
    assert int(opt.mesh_shade_option) == expected["mesh_shade_option"]
    assert opt.mesh_show_back_face == expected["mesh_show_back_face"]
    assert opt.mesh_show_wireframe == expected["mesh_show_wireframe"]
    assert opt.point_show_normal == expected["point_show_normal"]
    np.testing.assert_allclose(opt.default_mesh_color, expected["default_mesh_color"])
    np.testing.assert_allclose(opt.light_ambient_color, expected["light_ambient_color"])


def test_save_load_round_trip(tmp_path):
    opt = o3d.visualization.RenderOption()
    opt.background_color = [0.25, 0.5, 0.75]
    opt.point_size = 7.0
    opt.line_width = 3.0
    opt.light_on = False
    opt.point_show_normal = True
    opt.mesh_show_wireframe = True
    opt.mesh_show_back_face = True
    opt.mesh_shade_option = o3d.visualization.MeshShadeOption.SmoothShade
    opt.point_color_option = o3d.visualization.PointColorOption.ZCoordinate
    opt.mesh_color_option = o3d.visualization.MeshColorOption.Normal
    opt.default_mesh_color = [0.1, 0.2, 0.3]
    path = tmp_path / "opt.json"
    assert opt.save_to_json(str(path)) is True
    saved = json.loads(path.read_text())
    assert saved["class_name"] == "RenderOption"  # Open3D's layout
    assert saved["point_size"] == 7.0 and saved["point_color_option"] == 4
    back = o3d.visualization.RenderOption()
    back.load_from_json(path)  # os.PathLike accepted
    for name in ("point_size", "line_width", "light_on", "point_show_normal", "mesh_show_wireframe",
                 "mesh_show_back_face", "mesh_shade_option", "point_color_option", "mesh_color_option"):
        assert getattr(back, name) == getattr(opt, name), name
    for name in ("background_color", "default_mesh_color"):
        np.testing.assert_array_equal(getattr(back, name), getattr(opt, name))


def test_load_from_json_errors_leave_the_option_unchanged(tmp_path):
    opt = o3d.visualization.RenderOption()
    opt.point_size = 3.0
    with pytest.raises(FileNotFoundError):
        opt.load_from_json(str(tmp_path / "missing.json"))
    bad = tmp_path / "bad.json"
    bad.write_text('{"class_name": "RenderOption", "point_size": ')
    with pytest.raises(o3d.ParseError):
        opt.load_from_json(str(bad))
    other = tmp_path / "other.json"
    other.write_text('{"class_name": "ViewTrajectory", "point_size": 9}')
    with pytest.raises(o3d.ParseError):
        opt.load_from_json(str(other))
    assert opt.point_size == 3.0


def test_render_option_copies_are_values():
    import copy
    opt = o3d.visualization.RenderOption()
    twin = copy.copy(opt)
    twin.point_size = 9.0
    assert opt.point_size == 5.0
    assert o3d.visualization.RenderOption(twin).point_size == 9.0


# ---------------------------------------------------------------- MaterialRecord


def test_material_defaults_come_from_the_c_library():
    m = rendering.MaterialRecord()
    assert m.shader == "defaultLit"
    np.testing.assert_array_equal(m.base_color, [1.0, 1.0, 1.0, 1.0])
    assert m.point_size == 0.0 and m.line_width == 0.0
    m.base_color = [0.5, 0.25, 1.0]  # RGB: alpha 1
    np.testing.assert_array_equal(m.base_color, [0.5, 0.25, 1.0, 1.0])
    with pytest.raises(ValueError):
        m.base_color = [1.0, 2.0]


# ---------------------------------------------------------------- rendering


def test_background_fills_the_corners():
    r = renderer_with_camera(background=(0.2, 0.4, 0.6, 1.0))
    r.scene.add_geometry("cube", centred_cube([1.0, 0.0, 0.0]), unlit())
    img = rgb(r)
    assert img.shape == (H, W, 3) and img.dtype == np.uint8
    for row, col in ((0, 0), (0, W - 1), (H - 1, 0), (H - 1, W - 1)):
        assert_color(img[row, col], [0.2, 0.4, 0.6])
    np.testing.assert_array_equal(np.asarray(r.render_option.background_color), [0.2, 0.4, 0.6])


def test_default_background_is_white():
    r = rendering.OffscreenRenderer(32, 24)
    r.scene.add_geometry("cube", centred_cube([0.0, 0.0, 0.0]), unlit())
    img = rgb(r)
    assert (img[0, 0] == 255).all() and (img[-1, -1] == 255).all()


def test_unlit_cube_colour_depth_and_silhouette():
    color = [0.9, 0.3, 0.1]
    r = renderer_with_camera()
    r.scene.add_geometry("cube", centred_cube(color), unlit())
    img = rgb(r)
    row, col = project([0.0, 0.0, 0.5])
    assert_color(img[row, col], color)
    assert_color(img[0, 0], [0.0, 0.0, 0.0])

    depth = np.asarray(r.render_to_depth_image(z_in_view_space=True))
    assert depth.shape == (H, W) and depth.dtype == np.float32
    front_face = EYE_DISTANCE - 0.5
    assert abs(depth[row, col] - front_face) < 1e-3
    covered = depth > 0
    # Only the front face is visible: a plane perpendicular to the axis, so one depth everywhere.
    np.testing.assert_allclose(depth[covered], front_face, atol=1e-3)
    assert depth[0, 0] == 0.0
    # The face projects to a square of side F * 1 / 2.5 = 40 pixels.
    side = F * 1.0 / front_face
    assert abs(covered.sum() - side * side) <= 0.03 * side * side
    np.testing.assert_array_equal(covered, img.any(axis=2))

    buffer = np.asarray(r.render_to_depth_image())
    assert buffer[0, 0] == 1.0
    assert 0.0 < buffer[row, col] < 1.0


def test_sphere_silhouette_area_matches_the_pinhole_model():
    radius, f = 0.5, 200.0
    sphere = o3d.geometry.TriangleMesh.create_sphere(radius=radius, resolution=100)
    sphere.paint_uniform_color([1.0, 1.0, 1.0])
    r = renderer_with_camera(f=f)
    r.scene.add_geometry("sphere", sphere, unlit())
    area = (np.asarray(r.render_to_image()).max(axis=2) > 127).sum()
    expected = math.pi * (f * radius / math.sqrt(EYE_DISTANCE**2 - radius**2)) ** 2
    assert abs(area - expected) <= 0.03 * expected, (area, expected)
    depth = np.asarray(r.render_to_depth_image(z_in_view_space=True))
    assert abs(depth[H // 2, W // 2] - (EYE_DISTANCE - radius)) < 2e-3


def test_point_colours_at_their_projections():
    points = np.array([[-0.6, 0.4, 0.0], [0.5, -0.3, 0.2], [0.0, 0.0, -0.4]])
    colors = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.2, 0.4, 1.0]])
    pcd = o3d.geometry.PointCloud(points)
    pcd.colors = colors
    r = renderer_with_camera()
    r.scene.add_geometry("points", pcd, unlit())
    img = rgb(r)
    for p, c in zip(points, colors):
        assert_color(img[project(p)], c)
    # Points are squares of the default point size, 5 pixels: 25 pixels each, nothing else.
    assert img.any(axis=2).sum() == 3 * 25


def test_material_point_size_overrides_the_option():
    pcd = o3d.geometry.PointCloud(np.zeros((1, 3)))
    pcd.colors = [[1.0, 1.0, 1.0]]
    sizes = {}
    for size in (1.0, 9.0):
        r = renderer_with_camera()
        r.scene.add_geometry("p", pcd, unlit(point_size=size))
        sizes[size] = rgb(r).any(axis=2).sum()
    assert sizes == {1.0: 1, 9.0: 81}


def test_point_color_option_normal():
    pcd = o3d.geometry.PointCloud(np.zeros((1, 3)))
    pcd.normals = [[0.0, 0.0, 1.0]]
    r = renderer_with_camera()
    r.render_option.point_color_option = o3d.visualization.PointColorOption.Normal
    r.scene.add_geometry("p", pcd, unlit())
    assert_color(rgb(r)[project([0.0, 0.0, 0.0])], [0.5, 0.5, 1.0])


def test_line_set_and_boxes_draw_their_edges():
    ls = o3d.geometry.LineSet(np.array([[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]), np.array([[0, 1]]))
    ls.colors = [[0.0, 1.0, 0.0]]
    r = renderer_with_camera()
    r.scene.add_geometry("line", ls)
    img = rgb(r)
    row, col = project([0.5, 0.0, 0.0])
    assert any(np.abs(img[rr, col].astype(float) - [0, 255, 0]).max() <= 1 for rr in range(row - 1, row + 2))
    assert not img[row - 10].any()

    box = o3d.geometry.AxisAlignedBoundingBox([-0.5, -0.5, -0.5], [0.5, 0.5, 0.5])
    box.color = np.array([1.0, 0.0, 0.0])
    obb = o3d.geometry.OrientedBoundingBox([0.0, 0.0, 0.0], np.eye(3), [0.4, 0.4, 0.4])
    obb.color = np.array([0.0, 0.0, 1.0])
    r = renderer_with_camera()
    r.scene.add_geometry("aabb", box)
    r.scene.add_geometry("obb", obb)
    img = rgb(r)

    def near(point, color):
        row, col = project(point)
        patch = img[row - 1:row + 2, col - 1:col + 2].reshape(-1, 3).astype(float)
        return (np.abs(patch - to_u8(color)).max(axis=1) <= 1).any()

    assert near([0.0, 0.5, 0.5], [1.0, 0.0, 0.0])  # top edge of the box's front face
    assert near([0.0, -0.2, 0.2], [0.0, 0.0, 1.0])  # bottom edge of the small box's front face
    assert not img[project([0.0, 0.0, 0.5])].any()  # inside the faces: nothing


def test_voxel_grid_cube():
    pcd = o3d.geometry.PointCloud(np.zeros((1, 3)))
    pcd.colors = [[0.2, 0.8, 0.4]]
    grid = o3d.geometry.VoxelGrid.create_from_point_cloud(pcd, 1.0)  # one voxel: [-0.5, 0.5]^3
    r = renderer_with_camera()
    r.scene.add_geometry("grid", grid, unlit())
    row, col = project([0.0, 0.0, 0.5])
    assert_color(rgb(r)[row, col], [0.2, 0.8, 0.4])
    assert abs(np.asarray(r.render_to_depth_image(True))[row, col] - 2.5) < 1e-3


def test_scene_bookkeeping_and_copies():
    cube = centred_cube([1.0, 1.0, 1.0])
    r = renderer_with_camera()
    scene = r.scene
    scene.add_geometry("cube", cube, unlit())
    assert scene.has_geometry("cube") and not scene.has_geometry("other")
    centre = project([0.0, 0.0, 0.5])
    cube.translate([5.0, 0.0, 0.0])  # the renderer holds a copy
    assert rgb(r)[centre].all()
    scene.remove_geometry("cube")
    assert not scene.has_geometry("cube")
    assert not rgb(r)[centre].any()
    scene.add_geometry("a", centred_cube([1.0, 1.0, 1.0]), unlit())
    scene.add_geometry("b", centred_cube([1.0, 1.0, 1.0]), unlit())
    scene.clear_geometry()
    assert not scene.has_geometry("a") and not scene.has_geometry("b")


def test_render_option_is_live_and_assignable():
    r = renderer_with_camera()
    r.scene.add_geometry("cube", centred_cube([1.0, 1.0, 1.0]), unlit())
    r.render_option.background_color = [0.0, 0.0, 1.0]
    assert_color(rgb(r)[0, 0], [0.0, 0.0, 1.0])
    opt = o3d.visualization.RenderOption()
    opt.background_color = [1.0, 1.0, 0.0]
    r.render_option = opt
    assert_color(rgb(r)[0, 0], [1.0, 1.0, 0.0])
    snapshot = o3d.visualization.RenderOption(r.render_option)
    snapshot.background_color = [0.0, 0.0, 0.0]  # a copy: the renderer keeps its own
    assert_color(rgb(r)[0, 0], [1.0, 1.0, 0.0])


def test_get_camera_round_trip_reproduces_the_image():
    mesh = o3d.geometry.TriangleMesh.create_sphere(0.4, resolution=30)
    mesh.compute_vertex_normals()
    box = centred_cube([0.2, 0.6, 0.9])
    box.translate([0.6, 0.2, -0.3])

    def scene_renderer():
        r = rendering.OffscreenRenderer(W, H)
        r.scene.add_geometry("sphere", mesh)  # lit: shading depends on the camera too
        r.scene.add_geometry("box", box)
        return r

    for setup in (lambda r: None,  # Open3D's default view
                  lambda r: r.setup_camera_lookat([0.1, 0.0, 0.0], [0.3, 0.4, 1.0], [0.0, 1.0, 0.0], 0.6),
                  lambda r: r.setup_camera(45.0, [0.0, 0.0, 0.0], [1.0, 2.0, 3.0], [0.0, 1.0, 0.0])):
        first = scene_renderer()
        setup(first)
        params = first.get_camera()
        assert isinstance(params, o3d.camera.PinholeCameraParameters)
        assert (params.intrinsic.width, params.intrinsic.height) == (W, H)
        expected = rgb(first)
        second = scene_renderer()
        second.setup_camera(params.intrinsic, params.extrinsic)
        image = rgb(second)
        assert image.any(axis=2).sum() > 0 and not (image == expected[0, 0]).all()
        np.testing.assert_array_equal(image, expected)
        third = scene_renderer()
        third.setup_camera(params.intrinsic.intrinsic_matrix, params.extrinsic, W, H)
        np.testing.assert_array_equal(rgb(third), expected)


def test_get_camera_returns_the_pinhole_camera_set():
    r = renderer_with_camera()
    params = r.get_camera()
    np.testing.assert_allclose(params.extrinsic, EXTRINSIC, atol=1e-12)
    np.testing.assert_allclose(params.intrinsic.intrinsic_matrix, intrinsic().intrinsic_matrix, atol=1e-12)


def test_render_to_png_matches_render_to_image(tmp_path):
    r = renderer_with_camera()
    r.scene.add_geometry("cube", centred_cube([0.9, 0.3, 0.1]), unlit())
    path = tmp_path / "out.png"
    r.render_to_png(str(path))
    np.testing.assert_array_equal(np.asarray(o3d.io.read_image(str(path))), rgb(r))


def test_renderer_properties():
    r = rendering.OffscreenRenderer(W, H, backend="egl")
    assert r.backend == "egl"
    assert r.size == (W, H)


def test_errors_raise():
    for w, h in ((0, 10), (10, 0), (-1, 5), (16385, 10), (2**40, 10)):
        with pytest.raises(o3d.InvalidArgumentError):
            rendering.OffscreenRenderer(w, h)
    with pytest.raises(o3d.InvalidArgumentError):
        rendering.OffscreenRenderer(8, 8, backend="vulkan")
    r = renderer_with_camera()
    cube = centred_cube([1.0, 1.0, 1.0])
    r.scene.add_geometry("cube", cube)
    with pytest.raises(o3d.InvalidArgumentError):
        r.scene.add_geometry("cube", cube)  # duplicate name
    with pytest.raises(o3d.InvalidArgumentError):
        r.scene.add_geometry("", cube)
    with pytest.raises(o3d.InvalidArgumentError):
        r.scene.remove_geometry("missing")
    with pytest.raises(o3d.InvalidArgumentError):
        r.scene.add_geometry("normals", cube, _material_with_shader("normals"))  # checked when used
    with pytest.raises(TypeError):
        r.scene.add_geometry("wrong", np.zeros((3, 3)))
    with pytest.raises(o3d.InvalidArgumentError):
        r.setup_camera(intrinsic(W + 1, H), EXTRINSIC)  # the intrinsic's size is not the renderer's
    with pytest.raises(o3d.InvalidArgumentError):
        r.setup_camera(intrinsic().intrinsic_matrix, EXTRINSIC, W, H + 1)
    with pytest.raises(o3d.InvalidArgumentError):
        r.setup_camera(intrinsic(), np.diag([2.0, 1.0, 1.0, 1.0]))  # not rigid
    with pytest.raises(o3d.InvalidArgumentError):
        r.setup_camera(60.0, [0, 0, 0], [0, 0, 0], [0, 1, 0])  # eye == center
    with pytest.raises(o3d.InvalidArgumentError):
        r.setup_camera_lookat([0, 0, 0], [0, 0, 1], [0, 0, 1], 0.7)  # up parallel to front
    with pytest.raises(o3d.InvalidArgumentError):
        r.render_option.point_size = 100.0
    assert r.render_option.point_size == 5.0
    bad = o3d.visualization.RenderOption()
    bad.line_width = float("nan")
    with pytest.raises(o3d.InvalidArgumentError):
        r.render_option = bad
    with pytest.raises(o3d.UnsupportedError):
        r.scene.set_background([0, 0, 0, 1], image=o3d.geometry.Image())


def _material_with_shader(name):
    m = rendering.MaterialRecord()
    m.shader = name
    return m


def test_render_releases_the_gil():
    mesh = o3d.geometry.TriangleMesh.create_sphere(1.0, resolution=300)
    mesh.compute_vertex_normals()
    r = rendering.OffscreenRenderer(2048, 2048)
    r.scene.add_geometry("sphere", mesh)
    r.render_to_image()  # the first render uploads the mesh
    t0 = time.perf_counter()
    r.render_to_image()
    one_render = time.perf_counter() - t0
    if one_render < 0.03:  # a GPU: too fast to tell a held GIL from thread switching (5 ms)
        pytest.skip(f"one render takes {one_render:.3f} s: too fast to observe")
    stall, duration = max_stall_during(lambda: [r.render_to_image() for _ in range(3)])
    # Holding the GIL would stall the main thread for a whole render at least.
    assert stall < 0.5 * one_render, (stall, one_render)


def test_module_layout():
    import o3d.visualization as vis
    assert vis.rendering is rendering
    assert set(vis.__all__) >= {"RenderOption", "MeshShadeOption", "PointColorOption", "MeshColorOption"}
