"""o3d.geometry.HalfEdgeTriangleMesh and HalfEdge (halfedgemesh.h). Numbers marked "wheel" come from the open3d 0.20
wheel on the same input (HalfEdgeTriangleMesh.create_from_triangle_mesh of create_tetrahedron() and of a unit
square of two triangles)."""
import copy

import numpy as np
import pytest

import o3d

G = o3d.geometry


def square():
    return G.TriangleMesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float),
                          np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32))


def test_tetrahedron_half_edges():
    tet = G.TriangleMesh.create_tetrahedron()
    he = G.HalfEdgeTriangleMesh.create_from_triangle_mesh(tet)
    assert repr(he) == "HalfEdgeTriangleMesh with 4 points and 12 half edges."
    assert he.has_half_edges() and he.has_vertices() and he.has_vertex_normals() and not he.has_vertex_colors()
    assert np.allclose(he.vertices, np.asarray(tet.vertices))
    assert he.triangles.tolist() == [[0, 2, 1], [0, 3, 2], [0, 1, 3], [1, 2, 3]]  # wheel
    assert he.triangles.dtype == np.int32 and not he.triangles.flags.writeable and not he.vertices.flags.writeable
    n = he.vertex_normals
    assert np.allclose(n, he.vertices / np.linalg.norm(he.vertices, axis=1, keepdims=True))  # centred: radial
    assert he.triangle_normals.shape == (4, 3)
    edges = he.half_edges
    assert len(edges) == 12 and all(isinstance(h, G.HalfEdge) for h in edges)
    tris = he.triangles
    for i, h in enumerate(edges):
        t, k = divmod(i, 3)
        assert h.triangle_index == t and h.next == 3 * t + (k + 1) % 3
        assert h.vertex_indices.tolist() == [tris[t][k], tris[t][(k + 1) % 3]]
        assert not h.is_boundary() and edges[h.twin].twin == i
        assert edges[h.twin].vertex_indices.tolist() == h.vertex_indices.tolist()[::-1]
    ordered = [x.tolist() for x in he.ordered_half_edge_from_vertex]
    assert ordered == [[0, 6, 3], [2, 9, 7], [1, 5, 10], [4, 8, 11]]  # wheel
    assert he.get_boundaries() == []
    assert he.boundary_half_edges_from_vertex(0).tolist() == []  # Open3D raises here; the C API gives no loop
    assert he.get_center() == pytest.approx(np.asarray(tet.vertices).mean(axis=0))
    box = he.get_axis_aligned_bounding_box()
    assert box.get_min_bound() == pytest.approx(np.asarray(tet.vertices).min(axis=0))


def test_square_boundary():
    he = G.HalfEdgeTriangleMesh.create_from_triangle_mesh(square())
    got = [(h.next, h.twin, h.vertex_indices.tolist(), h.triangle_index) for h in he.half_edges]
    assert got == [(1, -1, [0, 1], 0), (2, -1, [1, 2], 0), (0, 3, [2, 0], 0),  # wheel
                   (4, 2, [0, 2], 1), (5, -1, [2, 3], 1), (3, -1, [3, 0], 1)]
    assert [h.is_boundary() for h in he.half_edges] == [True, True, False, False, True, True]
    assert [x.tolist() for x in he.ordered_half_edge_from_vertex] == [[0, 3], [1], [4, 2], [5]]  # wheel
    assert [b.tolist() for b in he.get_boundaries()] == [[0, 1, 2, 3]]  # wheel
    assert he.boundary_half_edges_from_vertex(2).tolist() == [4, 5, 0, 1]  # wheel
    assert he.boundary_vertices_from_vertex(2).tolist() == [2, 3, 0, 1]  # wheel
    assert np.allclose(he.vertex_normals, [[0, 0, 1]] * 4)  # wheel
    with pytest.raises(ValueError):
        he.boundary_vertices_from_vertex(4)
    with pytest.raises(ValueError):
        he.boundary_half_edges_from_vertex(-1)


def test_cleaning_colors_and_copies():
    mesh = square()
    mesh.vertices = np.vstack([np.asarray(mesh.vertices), [[5.0, 5.0, 5.0]]])  # unreferenced: dropped
    mesh.vertex_colors = np.tile([0.2, 0.4, 0.6], (5, 1))
    he = G.HalfEdgeTriangleMesh.create_from_triangle_mesh(mesh)
    assert len(he.vertices) == 4 and he.has_vertex_colors() and np.allclose(he.vertex_colors, [0.2, 0.4, 0.6])
    assert len(G.HalfEdgeTriangleMesh(he).half_edges) == 6
    assert len(copy.deepcopy(he).triangles) == 2
    empty = G.HalfEdgeTriangleMesh()
    assert empty.is_empty() and not empty.has_half_edges() and empty.vertices.shape == (0, 3)
    assert G.HalfEdgeTriangleMesh.create_from_triangle_mesh(G.TriangleMesh()).half_edges == []
    h = G.HalfEdge()
    assert (h.next, h.twin, h.triangle_index, h.vertex_indices.tolist()) == (-1, -1, -1, [-1, -1])
    assert repr(he.half_edges[0]) == "HalfEdge(vertex_indices {0, 1}, triangle_index 0, next 1, twin -1)"


def test_non_manifold_mesh_raises():
    fin = G.TriangleMesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float),
                         np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]], dtype=np.int32))
    with pytest.raises(o3d.InvalidArgumentError):
        G.HalfEdgeTriangleMesh.create_from_triangle_mesh(fin)
    with pytest.raises(TypeError):
        G.HalfEdgeTriangleMesh.create_from_triangle_mesh(G.PointCloud())
