"""o3d.geometry.TetraMesh: the container and its views, Vector4iVector, the Delaunay tetrahedralization of a
cloud (TetraMesh.create_from_point_cloud) and iso-surfaces (extract_triangle_mesh)."""
import copy
import itertools

import numpy as np
import pytest

import o3d

TetraMesh = o3d.geometry.TetraMesh
CUBE = np.array(list(itertools.product([0.0, 1.0], repeat=3)))


def volumes(mesh):
    """The (unsigned) volume of each tetrahedron."""
    v = np.asarray(mesh.vertices)[np.asarray(mesh.tetras)]
    return np.abs(np.einsum("ij,ij->i", v[:, 1] - v[:, 0], np.cross(v[:, 2] - v[:, 0], v[:, 3] - v[:, 0]))) / 6.0


def test_empty():
    mesh = TetraMesh()
    assert repr(mesh) == "TetraMesh with 0 points and 0 tetrahedra."
    assert mesh.is_empty() and not mesh.has_vertices() and not mesh.has_tetras()
    assert np.asarray(mesh.vertices).shape == (0, 3) and np.asarray(mesh.tetras).shape == (0, 4)
    assert np.asarray(mesh.tetras).dtype == np.int32


def test_construct_from_vectors_and_arrays():
    tetras = np.array([[0, 1, 2, 3]], dtype=np.int32)
    for v, t in ((o3d.utility.Vector3dVector(CUBE[:4]), o3d.utility.Vector4iVector(tetras)), (CUBE[:4], tetras),
                 (CUBE[:4].tolist(), [[0, 1, 2, 3]])):
        mesh = TetraMesh(v, t)
        assert repr(mesh) == "TetraMesh with 4 points and 1 tetrahedra."
        assert mesh.has_vertices() and mesh.has_tetras() and not mesh.is_empty()
        np.testing.assert_array_equal(np.asarray(mesh.vertices), CUBE[:4])
        np.testing.assert_array_equal(np.asarray(mesh.tetras), tetras)
    with pytest.raises(ValueError):
        TetraMesh(CUBE[:4], [[0, 1, 2]])  # not 4 indices
    with pytest.raises(ValueError):
        TetraMesh(CUBE[:4, :2], tetras)
    with pytest.raises(ValueError):
        TetraMesh(CUBE[:4], np.array([[0, 1, 2, 2**40]]))  # outside int32


def test_views_write_through_and_copies_are_independent():
    mesh = TetraMesh(CUBE[:4], [[0, 1, 2, 3]])
    np.asarray(mesh.vertices)[0] = [5.0, 6.0, 7.0]
    np.asarray(mesh.tetras)[0, 0] = 3
    np.testing.assert_array_equal(np.asarray(mesh.vertices)[0], [5.0, 6.0, 7.0])
    assert np.asarray(mesh.tetras)[0, 0] == 3
    for other in (copy.copy(mesh), copy.deepcopy(mesh), TetraMesh(mesh)):
        np.asarray(other.vertices)[0] = 0.0
        np.testing.assert_array_equal(np.asarray(mesh.vertices)[0], [5.0, 6.0, 7.0])
        assert repr(other) == repr(mesh)
    view = np.asarray(mesh.vertices)
    mesh.vertices = CUBE  # replacing while a view is alive: the view keeps the old data
    assert view.shape == (4, 3) and len(mesh.vertices) == 8
    assert mesh.clear() is mesh and mesh.is_empty() and not mesh.has_tetras()
    assert view[0, 0] == 5.0


def test_vector4ivector():
    v = o3d.utility.Vector4iVector(np.arange(8).reshape(2, 4))
    assert len(v) == 2 and np.asarray(v).dtype == np.int32 and np.asarray(v).shape == (2, 4)
    v.append([8, 9, 10, 11])
    np.testing.assert_array_equal(np.asarray(v)[2], [8, 9, 10, 11])
    assert np.asarray(o3d.utility.Vector4iVector()).shape == (0, 4)
    with pytest.raises(ValueError):
        o3d.utility.Vector4iVector(np.zeros((2, 3)))


def test_delaunay_of_the_cube_corners():
    pcd = o3d.geometry.PointCloud(CUBE)
    mesh, pt_map = TetraMesh.create_from_point_cloud(pcd)
    assert isinstance(mesh, TetraMesh) and isinstance(pt_map, list)
    assert sorted(pt_map) == list(range(8))
    np.testing.assert_array_equal(np.asarray(mesh.vertices), CUBE[pt_map])
    assert len(mesh.tetras) in (5, 6)
    assert volumes(mesh).sum() == pytest.approx(1.0, abs=1e-12)
    assert np.all(volumes(mesh) > 0)


def test_delaunay_property_of_a_random_cloud():
    rng = np.random.default_rng(4)
    points = rng.uniform(size=(60, 3))
    mesh, pt_map = TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(points))
    v = np.asarray(mesh.vertices)
    np.testing.assert_array_equal(v, points[pt_map])
    hull, _ = o3d.geometry.PointCloud(points).compute_convex_hull()
    assert volumes(mesh).sum() == pytest.approx(hull.get_volume(), rel=1e-9)  # the tetras tile the hull
    # empty circumsphere: no vertex lies strictly inside any tetrahedron's circumsphere
    for tet in np.asarray(mesh.tetras):
        p = v[tet]
        a = 2.0 * (p[1:] - p[0])
        b = np.sum(p[1:] ** 2, axis=1) - np.sum(p[0] ** 2)
        center = np.linalg.solve(a, b)
        r = np.linalg.norm(p[0] - center)
        assert np.all(np.linalg.norm(v - center, axis=1) >= r * (1.0 - 1e-9))


def test_duplicate_points_share_a_vertex():
    points = np.vstack([CUBE, CUBE[:2]])  # two repeats
    mesh, pt_map = TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(points))
    assert len(mesh.vertices) == 8 and len(pt_map) == 8
    np.testing.assert_array_equal(np.asarray(mesh.vertices), points[pt_map])


def test_create_from_point_cloud_errors():
    with pytest.raises(o3d.InvalidArgumentError):
        TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(CUBE[:3]))
    flat = np.column_stack([np.random.default_rng(5).uniform(size=(20, 2)), np.zeros(20)])
    with pytest.raises(o3d.InvalidArgumentError):
        TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(flat))
    with pytest.raises(o3d.InvalidArgumentError):
        TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(np.vstack([CUBE, [[np.nan, 0.0, 0.0]]])))
    with pytest.raises(TypeError):
        TetraMesh.create_from_point_cloud(None)


def test_linear_field_gives_a_plane():
    rng = np.random.default_rng(6)
    points = np.vstack([CUBE, rng.uniform(size=(200, 3))])
    mesh, _ = TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(points))
    x = np.asarray(mesh.vertices)[:, 0]
    for values in (x, x.tolist(), o3d.utility.DoubleVector(x)):
        plane = mesh.extract_triangle_mesh(values, 0.3)
        assert isinstance(plane, o3d.geometry.TriangleMesh) and len(plane.triangles) > 0
        np.testing.assert_allclose(np.asarray(plane.vertices)[:, 0], 0.3, atol=1e-12)
        assert plane.get_surface_area() == pytest.approx(1.0, rel=1e-9)  # the unit cube's cross-section
    assert len(mesh.extract_triangle_mesh(x, 2.0).triangles) == 0  # the level is outside the values


def test_extract_triangle_mesh_errors():
    mesh, _ = TetraMesh.create_from_point_cloud(o3d.geometry.PointCloud(CUBE))
    with pytest.raises(o3d.InvalidArgumentError):
        mesh.extract_triangle_mesh(np.zeros(7), 0.5)  # one value short
    with pytest.raises(o3d.InvalidArgumentError):
        mesh.extract_triangle_mesh(np.zeros(8), np.nan)
    with pytest.raises(o3d.InvalidArgumentError):
        mesh.extract_triangle_mesh(np.zeros((8, 1)), 0.5)  # not 1-D
    with pytest.raises(o3d.InvalidArgumentError):
        mesh.extract_triangle_mesh(None, 0.5)
    bad = TetraMesh(CUBE[:4], [[0, 1, 2, 9]])  # a tetra index past the vertices
    with pytest.raises(o3d.InvalidArgumentError):
        bad.extract_triangle_mesh(np.zeros(4), 0.5)
