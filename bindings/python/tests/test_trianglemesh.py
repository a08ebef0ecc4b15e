"""o3d.geometry.TriangleMesh container: zero-copy views, attributes, queries, transforms, clean-up, errors.

Reference numbers: tools/reference/record_python_geometry.py (Open3D 0.20.0).
"""
import copy
import gc
import pickle

import numpy as np
import pytest

import o3d

TM = o3d.geometry.TriangleMesh


def fp(a):
    """sum_i (i + 1) * a_i over the flattened array, as in the recording script."""
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def unit_square():
    return TM(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64),
              np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32))


def test_box_area_volume_and_topology():
    box = TM.create_box()
    assert len(box.vertices) == 8 and len(box.triangles) == 12
    assert box.get_surface_area() == pytest.approx(6.0)
    assert box.get_volume() == pytest.approx(1.0)
    assert box.is_watertight() and box.is_edge_manifold() and box.is_vertex_manifold()
    assert box.is_orientable() and not box.is_self_intersecting()
    assert box.euler_poincare_characteristic() == 2
    # Open3D 0.20: same vertex and triangle order
    assert fp(box.vertices) == pytest.approx(192.0)
    assert fp(box.triangles) == pytest.approx(2246.0)


def test_box_normals_match_open3d():
    box = TM.create_box().compute_vertex_normals()
    assert box.has_vertex_normals() and box.has_triangle_normals()
    np.testing.assert_allclose(np.linalg.norm(np.asarray(box.vertex_normals), axis=1), 1.0)
    assert fp(box.vertex_normals) == pytest.approx(48.49742261192857, abs=1e-9)
    assert fp(box.triangle_normals) == pytest.approx(-12.0, abs=1e-9)


def test_views_are_zero_copy_and_write_through():
    mesh = TM.create_box()
    v = np.asarray(mesh.vertices)
    assert v.dtype == np.float64 and v.shape == (8, 3) and v.flags.writeable and not v.flags.owndata
    assert np.shares_memory(v, np.asarray(mesh.vertices))
    v *= 2.0  # the library sees the edit
    assert mesh.get_surface_area() == pytest.approx(24.0)
    assert mesh.get_volume() == pytest.approx(8.0)
    t = np.asarray(mesh.triangles)
    assert t.dtype == np.int32 and t.shape == (12, 3) and np.shares_memory(t, np.asarray(mesh.triangles))
    t[:] = t[:, ::-1]  # flip every triangle through the view: the library sees inward normals
    np.testing.assert_array_equal(mesh._array_copy(100), t)
    mesh.compute_triangle_normals()
    assert fp(mesh.triangle_normals) == pytest.approx(12.0)  # Open3D's box gives -12 before the flip
    assert mesh.get_volume() == pytest.approx(8.0)  # Open3D 0.20 reports |volume| for an inward box too
    # compute_triangle_normals resized an array while views were alive: the mesh took a private copy,
    # so the old views keep the old memory and fresh views see the new one
    ro = mesh._readonly_view(0)
    assert not ro.flags.writeable and np.shares_memory(ro, np.asarray(mesh.vertices))
    assert not np.shares_memory(ro, v)
    np.testing.assert_array_equal(ro, v)


def test_view_survives_mesh_deletion_and_resize():
    mesh = TM.create_box()
    v = np.asarray(mesh.vertices)
    expected = v.copy()
    mesh.vertices = np.zeros((3, 3))  # reallocation: the old view keeps the old data
    np.testing.assert_array_equal(v, expected)
    assert len(mesh.vertices) == 3
    del mesh
    gc.collect()
    np.testing.assert_array_equal(v, expected)


def test_attributes_and_has():
    mesh = unit_square()
    assert mesh.has_vertices() and mesh.has_triangles()
    assert not mesh.has_vertex_normals() and not mesh.has_vertex_colors() and not mesh.has_triangle_uvs()
    mesh.vertex_colors = o3d.utility.Vector3dVector(np.full((4, 3), 0.5))
    assert mesh.has_vertex_colors()
    mesh.vertex_colors = np.zeros((3, 3))  # wrong row count: present but not counted (Open3D semantics)
    assert not mesh.has_vertex_colors()
    uvs = np.arange(12, dtype=np.float64).reshape(6, 2) / 12
    mesh.triangle_uvs = o3d.utility.Vector2dVector(uvs)
    assert mesh.has_triangle_uvs()
    np.testing.assert_array_equal(np.asarray(mesh.triangle_uvs), uvs)
    mesh.triangle_material_ids = o3d.utility.IntVector([0, 0])
    assert mesh.has_triangle_material_ids()
    assert np.asarray(mesh.triangle_material_ids).shape == (2,)
    mesh.triangles = o3d.utility.Vector3iVector(np.array([[0, 1, 2]]))
    assert len(mesh.triangles) == 1
    assert "4 points and 1 triangles" in repr(mesh)
    assert not TM().has_vertices() and TM().is_empty()


def test_textures_list():
    mesh = unit_square()
    assert not mesh.has_textures()
    tex = o3d.geometry.Image(np.arange(12, dtype=np.uint8).reshape(2, 2, 3))
    mesh.textures = [tex, tex]
    assert mesh.has_textures() and len(mesh.textures) == 2
    np.testing.assert_array_equal(np.asarray(mesh.textures[1]), np.asarray(tex))
    mesh.textures = []
    assert not mesh.has_textures()
    with pytest.raises(TypeError):
        mesh.textures = [1]


def test_transforms_and_bounds():
    mesh = TM.create_box()
    np.testing.assert_allclose(mesh.get_center(), [0.5, 0.5, 0.5])
    mesh.translate((1.0, 2.0, 3.0))
    np.testing.assert_allclose(mesh.get_min_bound(), [1, 2, 3])
    np.testing.assert_allclose(mesh.get_max_bound(), [2, 3, 4])
    mesh.translate((0.0, 0.0, 0.0), relative=False)
    np.testing.assert_allclose(mesh.get_center(), [0, 0, 0], atol=1e-12)
    mesh.scale(2.0, center=(0, 0, 0))
    np.testing.assert_allclose(mesh.get_max_bound(), [1, 1, 1])
    R = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1]], dtype=np.float64)
    mesh.rotate(R, center=(0, 0, 0))
    assert mesh.get_surface_area() == pytest.approx(24.0)
    T = np.eye(4)
    T[:3, 3] = [10, 0, 0]
    mesh.transform(T)
    box = mesh.get_axis_aligned_bounding_box()
    assert isinstance(box, o3d.geometry.AxisAlignedBoundingBox)
    np.testing.assert_allclose(box.get_min_bound(), [9, -1, -1])
    np.testing.assert_allclose(box.get_extent(), [2, 2, 2])


def test_add_and_iadd_and_copy():
    a = TM.create_box()
    b = TM.create_box().translate((3, 0, 0))
    c = a + b
    assert len(c.vertices) == 16 and len(c.triangles) == 24
    assert np.asarray(c.triangles).max() == 15
    assert len(a.vertices) == 8
    a += a  # appends a snapshot of itself
    assert len(a.triangles) == 24
    d = copy.deepcopy(c)
    np.asarray(d.vertices)[:] = 0
    assert c.get_surface_area() == pytest.approx(12.0)
    e = TM(c)
    assert e.get_surface_area() == pytest.approx(12.0)


def test_cluster_connected_triangles_two_boxes():
    two = TM.create_box() + TM.create_box().translate((3, 0, 0))
    clusters, n, area = two.cluster_connected_triangles()
    # Open3D 0.20: clusters [0]*12 + [1]*12, n [12, 12], area [6, 6]
    np.testing.assert_array_equal(clusters, [0] * 12 + [1] * 12)
    np.testing.assert_array_equal(n, [12, 12])
    np.testing.assert_allclose(area, [6.0, 6.0])
    assert clusters.dtype == np.int32 and area.dtype == np.float64


def test_cleanup_functions():
    # two copies of a square sharing nothing: duplicated vertices, duplicated triangles, an unused vertex
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]] * 2 + [[5, 5, 5]], dtype=np.float64)
    t = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7], [0, 0, 1]], dtype=np.int32)
    mesh = TM(v, t)
    assert mesh.remove_duplicated_vertices() is mesh
    assert len(mesh.vertices) == 5
    mesh.remove_duplicated_triangles()
    assert len(mesh.triangles) == 3
    mesh.remove_degenerate_triangles()
    assert len(mesh.triangles) == 2
    mesh.remove_unreferenced_vertices()
    assert len(mesh.vertices) == 4
    assert mesh.get_surface_area() == pytest.approx(1.0)
    near = TM(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1e-4, 0, 0]], dtype=np.float64),
              np.array([[0, 1, 2], [3, 1, 2]], dtype=np.int32))
    near.merge_close_vertices(0.01)
    assert len(near.vertices) == 3
    # four triangles on one edge: non-manifold until two are removed
    fan = TM(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64),
             np.array([[0, 1, 2], [0, 1, 3], [0, 1, 4], [0, 1, 5]], dtype=np.int32))
    assert not fan.is_edge_manifold()
    fan.remove_non_manifold_edges()
    assert fan.is_edge_manifold() and len(fan.triangles) == 2


def test_open_mesh_queries():
    sq = unit_square()
    assert not sq.is_watertight()
    assert sq.is_edge_manifold(allow_boundary_edges=True)
    assert not sq.is_edge_manifold(allow_boundary_edges=False)
    assert sq.euler_poincare_characteristic() == 1
    with pytest.raises(ValueError):
        sq.get_volume()


def test_paint_and_normalize():
    mesh = TM.create_box()
    mesh.paint_uniform_color([0.1, 0.2, 0.3])
    np.testing.assert_allclose(np.asarray(mesh.vertex_colors), np.tile([0.1, 0.2, 0.3], (8, 1)))
    mesh.compute_vertex_normals(normalized=False)
    mesh.normalize_normals()
    np.testing.assert_allclose(np.linalg.norm(np.asarray(mesh.vertex_normals), axis=1), 1.0)


def test_bad_input_raises():
    mesh = TM(np.zeros((3, 3)), np.array([[0, 1, 7]], dtype=np.int32))  # index out of range
    with pytest.raises(ValueError):
        mesh.compute_vertex_normals()
    with pytest.raises(ValueError):
        mesh.get_surface_area()
    with pytest.raises(ValueError):
        TM().vertices = np.zeros((4, 2))
    with pytest.raises(ValueError):
        TM().triangles = np.zeros((2, 3), dtype=np.float64)  # floats are not indices
    with pytest.raises(ValueError):
        TM().triangles = np.array([[0, 1, 2**40]])
    with pytest.raises(ValueError):
        TM.create_box().translate((1, 2))
    with pytest.raises(o3d.O3DError):
        TM.create_box().merge_close_vertices(-1.0)


def test_pickle_roundtrip_keeps_everything():
    box = TM.create_box().compute_vertex_normals()
    box.triangle_uvs = np.random.default_rng(2).uniform(size=(36, 2))
    box.triangle_material_ids = np.arange(12, dtype=np.int32) % 2
    box.textures = [o3d.geometry.Image(np.full((2, 2, 3), 9, dtype=np.uint8))]
    back = pickle.loads(pickle.dumps(box))
    for name in ("vertices", "vertex_normals", "triangles", "triangle_normals", "triangle_uvs",
                 "triangle_material_ids"):
        np.testing.assert_array_equal(np.asarray(getattr(back, name)), np.asarray(getattr(box, name)), err_msg=name)
    assert not back.has_vertex_colors()
    np.testing.assert_array_equal(np.asarray(back.textures[0]), np.asarray(box.textures[0]))
    assert pickle.loads(pickle.dumps(TM())).is_empty()
