"""TriangleMesh.remove_vertices_by_index / _by_mask and remove_triangles_by_index / _by_mask: Open3D's semantics
(a removed vertex takes its triangles; removed triangles leave every vertex), the Poisson density trim, errors."""
import numpy as np
import pytest

import o3d


def tagged_sphere():
    """A sphere whose vertex colours record each vertex's original index (red channel, scaled)."""
    mesh = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=10)
    n = len(mesh.vertices)
    mesh.vertex_colors = np.column_stack([np.arange(n) / n, np.zeros(n), np.zeros(n)])
    return mesh


def test_remove_vertices_by_mask_drops_their_triangles():
    mesh = tagged_sphere()
    vertices = np.asarray(mesh.vertices).copy()
    triangles = np.asarray(mesh.triangles).copy()
    mask = vertices[:, 2] > 0.5
    assert mesh.remove_vertices_by_mask(mask) is None
    kept = np.flatnonzero(~mask)
    np.testing.assert_array_equal(np.asarray(mesh.vertices), vertices[kept])
    np.testing.assert_allclose(np.asarray(mesh.vertex_colors)[:, 0] * len(vertices), kept)
    survivors = triangles[~mask[triangles].any(axis=1)]
    renumber = np.full(len(vertices), -1)
    renumber[kept] = np.arange(len(kept))
    np.testing.assert_array_equal(np.asarray(mesh.triangles), renumber[survivors])
    assert not mesh.is_watertight()


def test_remove_vertices_by_index_equals_by_mask():
    a, b = tagged_sphere(), tagged_sphere()
    a.remove_vertices_by_index([3, 7, 7, 0])
    mask = np.zeros(len(b.vertices), dtype=bool)
    mask[[0, 3, 7]] = True
    b.remove_vertices_by_mask(mask)
    np.testing.assert_array_equal(np.asarray(a.vertices), np.asarray(b.vertices))
    np.testing.assert_array_equal(np.asarray(a.triangles), np.asarray(b.triangles))


def test_remove_triangles_keeps_the_vertices():
    mesh = o3d.geometry.TriangleMesh.create_box()
    triangles = np.asarray(mesh.triangles).copy()
    mesh.remove_triangles_by_index(np.array([0, 11]))
    np.testing.assert_array_equal(np.asarray(mesh.triangles), triangles[1:11])
    mask = np.zeros(10, dtype=bool)
    mask[4] = True
    mesh.remove_triangles_by_mask(mask)
    assert len(mesh.triangles) == 9 and len(mesh.vertices) == 8


def test_poisson_density_trim():
    rng = np.random.default_rng(3)
    d = rng.normal(size=(4000, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    pcd = o3d.geometry.PointCloud(d)
    pcd.normals = d
    mesh, densities = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=5)
    densities = np.asarray(densities)
    low = densities < np.quantile(densities, 0.25)
    before = len(mesh.vertices)
    mesh.remove_vertices_by_mask(low)
    assert len(mesh.vertices) == before - low.sum()


def test_removal_errors_leave_the_mesh_alone():
    mesh = o3d.geometry.TriangleMesh.create_box()
    with pytest.raises(ValueError):
        mesh.remove_vertices_by_index([8])
    with pytest.raises(ValueError):
        mesh.remove_vertices_by_index([-1])
    with pytest.raises(ValueError):
        mesh.remove_vertices_by_mask(np.zeros(7, dtype=bool))
    with pytest.raises(ValueError):
        mesh.remove_triangles_by_index([12])
    with pytest.raises(ValueError):
        mesh.remove_triangles_by_mask([True] * 13)
    with pytest.raises(ValueError):
        mesh.remove_vertices_by_mask(np.zeros(8, dtype=float))
    assert len(mesh.vertices) == 8 and len(mesh.triangles) == 12
