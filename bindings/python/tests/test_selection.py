"""o3d.visualization.SelectionPolygonVolume and VisualizerWithEditing's crop. Reference numbers recorded from the
open3d 0.20 wheel: read_selection_polygon_volume("Crop/cropped.json") on fragment.pcd keeps 29873 of 113662
points (crop_in_polygon starts 124..128 and ends 113659..113661); on knot.ply with the volume below
(orthogonal_axis "Z", range [-100, 0], the rectangle x in [-100, 10], y in [-40, 40]) crop_triangle_mesh keeps
614 vertices and 1020 triangles."""
import numpy as np
import pytest

import o3d

vis_module = o3d.visualization


def _grid_cloud(z=0.0):
    """30 x 30 points of step 0.1 from -0.95: exactly 100 inside [0, 1]^2, none on its edges."""
    g = -0.95 + 0.1 * np.arange(30)
    x, y = np.meshgrid(g, g, indexing="ij")
    return o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.c_[x.ravel(), y.ravel(), np.full(900, z)]))


def _unit_square():
    vol = vis_module.SelectionPolygonVolume()
    vol.orthogonal_axis = "Z"
    vol.axis_min, vol.axis_max = 0.0, 1.0
    vol.bounding_polygon = o3d.utility.Vector3dVector([[0, 0, 5], [1, 0, 5], [1, 1, 5], [0, 1, 5]])
    return vol


def test_unit_square_crops_the_grid():
    vol = _unit_square()
    kept = vol.crop_point_cloud(_grid_cloud(0.5))
    pts = np.asarray(kept.points)
    assert len(pts) == 100
    assert ((pts[:, :2] > 0) & (pts[:, :2] < 1)).all()
    assert len(vol.crop_point_cloud(_grid_cloud(1.5)).points) == 0  # above axis_max
    indices = vol.crop_in_polygon(_grid_cloud(0.5))
    assert indices[0] == 10 * 30 + 10 and len(indices) == 100
    assert vol.orthogonal_axis == "Z"
    np.testing.assert_array_equal(np.asarray(vol.bounding_polygon)[:, 2], 5.0)


def test_properties_and_errors():
    vol = vis_module.SelectionPolygonVolume()
    assert vol.orthogonal_axis == "Y"
    vol.orthogonal_axis = "x"
    assert vol.orthogonal_axis == "X"
    with pytest.raises(ValueError):
        vol.orthogonal_axis = "W"
    with pytest.raises(ValueError):
        vol.axis_min = float("nan")
    with pytest.raises(ValueError):
        vol.crop_point_cloud(_grid_cloud())  # no polygon yet
    vol.bounding_polygon = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    vol.axis_min, vol.axis_max = 2.0, 1.0
    with pytest.raises(ValueError):
        vol.crop_point_cloud(_grid_cloud())  # axis_min > axis_max


def test_bad_json_raises(tmp_path):
    path = tmp_path / "v.json"
    path.write_text('{"class_name": "SelectionPolygonVolume", "orthogonal_axis": "Y", "axis_min": 0}')
    with pytest.raises(o3d.ParseError):
        vis_module.read_selection_polygon_volume(str(path))
    with pytest.raises(OSError):
        vis_module.read_selection_polygon_volume(str(tmp_path / "missing.json"))


def test_open3d_fragment_reference(data_file):
    vol = vis_module.read_selection_polygon_volume(data_file("open3d/Crop/cropped.json"))
    assert vol.orthogonal_axis == "Y"
    assert len(vol.bounding_polygon) == 20
    pcd = o3d.io.read_point_cloud(data_file("open3d/fragment.pcd"))
    chair = vol.crop_point_cloud(pcd)
    assert len(chair.points) == 29873
    np.testing.assert_allclose(np.asarray(chair.points).sum(axis=0),
                               [72136.99282503, 53441.75809902, 39966.93971372], rtol=1e-9)
    indices = vol.crop_in_polygon(pcd)
    assert indices[:5] == [124, 125, 126, 127, 128] and indices[-3:] == [113659, 113660, 113661]


def test_open3d_knot_mesh_reference(data_file):
    mesh = o3d.io.read_triangle_mesh(data_file("open3d/knot.ply"))
    vol = vis_module.SelectionPolygonVolume()
    vol.orthogonal_axis = "Z"
    vol.axis_min, vol.axis_max = -100.0, 0.0
    vol.bounding_polygon = o3d.utility.Vector3dVector([[-100, -40, 0], [10, -40, 0], [10, 40, 0], [-100, 40, 0]])
    cropped = vol.crop_triangle_mesh(mesh)
    assert len(cropped.triangles) == 1020
    assert len(cropped.vertices) == 614


def test_editing_viewer_crops_a_dragged_rectangle(tmp_path):
    vis = vis_module.VisualizerWithEditing(directory=str(tmp_path))
    assert vis.create_window("crop", 160, 120, visible=False)
    cloud = _grid_cloud()
    vis.add_geometry(cloud)
    assert vis.get_cropped_geometry() is None
    before = np.asarray(vis.capture_screen_float_buffer())
    vis.send_key_event(ord("K"))
    assert vis.is_selecting()
    params = vis.get_view_control().convert_to_pinhole_camera_parameters()
    vis.send_mouse_move(50, 40)
    vis.send_mouse_button(0, 1)
    vis.send_mouse_move(110, 80)
    vis.send_mouse_button(0, 0)
    after_drag = vis.get_view_control().convert_to_pinhole_camera_parameters()
    np.testing.assert_array_equal(params.extrinsic, after_drag.extrinsic)  # the view is locked
    # The points expected to survive: their projections through the view's camera fall inside the rectangle.
    k = params.intrinsic.intrinsic_matrix
    cam = (params.extrinsic[:3, :3] @ np.asarray(cloud.points).T).T + params.extrinsic[:3, 3]
    u = k[0, 0] * cam[:, 0] / cam[:, 2] + k[0, 2]
    v = k[1, 1] * cam[:, 1] / cam[:, 2] + k[1, 2]
    expected = int(((u > 50) & (u < 110) & (v > 40) & (v < 80)).sum())
    assert 20 < expected < 900
    vis.send_key_event(ord("C"))
    assert not vis.is_selecting()
    cropped = vis.get_cropped_geometry()
    assert isinstance(cropped, o3d.geometry.PointCloud) and len(cropped.points) == expected
    written = o3d.io.read_point_cloud(str(tmp_path / "cropped_1.ply"))
    assert len(written.points) == expected
    after = np.asarray(vis.capture_screen_float_buffer())
    assert (after < 0.99).any(axis=2).sum() < (before < 0.99).any(axis=2).sum()  # fewer points drawn
    vis.destroy_window()
