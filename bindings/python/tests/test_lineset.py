"""o3d.geometry.LineSet: arrays, paint, transform and the create_from_* constructors.

Reference numbers: tools/reference/record_python_round2.py (Open3D 0.20.0).
"""
import copy

import numpy as np
import pytest

import o3d
from round2_data import fp, rot_xyz

LS = o3d.geometry.LineSet
# Open3D 0.20: the 12 box edges of create_from_{oriented,axis_aligned}_bounding_box
BOX_LINES = [[0, 1], [1, 7], [7, 2], [2, 0], [3, 6], [6, 4], [4, 5], [5, 3], [0, 3], [1, 6], [7, 4], [2, 5]]
AABB_POINTS = [[-1.0, -2.0, -3.0], [1.0, -2.0, -3.0], [-1.0, 2.0, -3.0], [-1.0, -2.0, 3.0], [1.0, 2.0, 3.0],
               [-1.0, 2.0, 3.0], [1.0, -2.0, 3.0], [1.0, 2.0, -3.0]]


def square():
    pts = np.array([[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    return LS(points=o3d.utility.Vector3dVector(pts), lines=o3d.utility.Vector2iVector([[0, 1], [1, 2], [2, 3], [3, 0]]))


def test_empty_and_constructor():
    ls = LS()
    assert not ls.has_points() and not ls.has_lines() and not ls.has_colors() and ls.is_empty()
    assert np.asarray(ls.points).shape == (0, 3) and np.asarray(ls.lines).shape == (0, 2)
    ls = square()
    assert ls.has_points() and ls.has_lines() and not ls.has_colors()
    lines = np.asarray(ls.lines)
    assert lines.dtype == np.int32 and lines.tolist() == [[0, 1], [1, 2], [2, 3], [3, 0]]
    assert np.asarray(ls.points)[2].tolist() == [1, 1, 0]
    p, l, c = (ls._array_copy(w) for w in (0, 100, 1))
    assert np.array_equal(p, np.asarray(ls.points)) and np.array_equal(l, lines) and c.shape == (0, 3)


def test_paint_transform_copy():
    ls = square()
    assert ls.paint_uniform_color((0.2, 0.4, 0.6)) is ls
    assert ls.has_colors() and np.allclose(np.asarray(ls.colors), [[0.2, 0.4, 0.6]] * 4)
    other = copy.deepcopy(ls)
    T = np.eye(4)
    T[:3, :3] = rot_xyz(0, 0, np.pi / 2)
    T[:3, 3] = [1, 2, 3]
    ls.transform(T)
    assert np.allclose(np.asarray(ls.points)[1], [1, 3, 3])
    assert np.allclose(np.asarray(other.points)[1], [1, 0, 0])  # the copy is independent
    ls.colors = np.zeros((4, 3))
    assert np.array_equal(np.asarray(ls.colors), np.zeros((4, 3)))


def test_from_triangle_mesh_box_edges():
    ls = LS.create_from_triangle_mesh(o3d.geometry.TriangleMesh.create_box())
    assert len(ls.lines) == 18  # 12 cube edges + 6 face diagonals (Open3D 0.20)
    assert sorted(tuple(sorted(map(int, l))) for l in np.asarray(ls.lines)) == [
        (0, 1), (0, 2), (0, 4), (1, 2), (1, 3), (1, 4), (1, 5), (1, 7), (2, 3), (2, 4), (2, 6), (2, 7), (3, 7),
        (4, 5), (4, 6), (4, 7), (5, 7), (6, 7)]
    assert len(ls.points) == 8


def test_from_boxes():
    aabb = o3d.geometry.AxisAlignedBoundingBox((-1, -2, -3), (1, 2, 3))
    ls = LS.create_from_axis_aligned_bounding_box(aabb)
    assert np.asarray(ls.lines).tolist() == BOX_LINES and np.array_equal(np.asarray(ls.points), AABB_POINTS)
    # every edge has the length of one of the box's sides (analytic)
    p = np.asarray(ls.points)
    lengths = sorted(np.linalg.norm(p[a] - p[b]) for a, b in BOX_LINES)
    assert lengths == pytest.approx([2.0] * 4 + [4.0] * 4 + [6.0] * 4)
    box = o3d.geometry.OrientedBoundingBox((1.0, 2.0, 3.0), rot_xyz(0.3, -0.2, 0.5), (2.0, 1.0, 0.5))
    ls = LS.create_from_oriented_bounding_box(box)
    assert np.asarray(ls.lines).tolist() == BOX_LINES
    assert fp(ls.points) == pytest.approx(663.2638357021638, rel=1e-12)  # Open3D 0.20


def test_from_correspondences():
    a = o3d.geometry.PointCloud(np.array([[0.0, 0, 0], [1, 0, 0]]))
    b = o3d.geometry.PointCloud(np.array([[0.0, 5, 0], [1, 5, 0], [2, 5, 0]]))
    ls = LS.create_from_point_cloud_correspondences(a, b, [(0, 2), (1, 0)])
    assert len(ls.points) == 5 and np.asarray(ls.lines).tolist() == [[0, 4], [1, 2]]
    ls = LS.create_from_point_cloud_correspondences(a, b, o3d.utility.Vector2iVector([[1, 1]]))
    assert np.asarray(ls.lines).tolist() == [[1, 3]]


def test_errors():
    a = o3d.geometry.PointCloud(np.zeros((2, 3)))
    with pytest.raises(ValueError):
        LS.create_from_point_cloud_correspondences(a, a, [(0, 2)])
    with pytest.raises(ValueError):
        LS.create_from_point_cloud_correspondences(a, a, [(0.5, 1)])
    with pytest.raises(ValueError):
        LS(points=np.zeros((2, 3)), lines=np.zeros((2, 3), dtype=int))
    with pytest.raises(ValueError):
        LS(points=np.zeros((2, 3)), lines=[[0, 2**40]])
    ls = square()
    with pytest.raises(ValueError):
        ls.paint_uniform_color((1.0, 2.0))
    with pytest.raises(ValueError):
        ls.transform(np.eye(3))
    with pytest.raises(ValueError):
        LS.create_from_oriented_bounding_box(o3d.geometry.OrientedBoundingBox(np.zeros(3), np.eye(3), (1, -1, 1)))
    with pytest.raises(TypeError):
        LS.create_from_axis_aligned_bounding_box(None)
    # triangles pointing past the vertices are caught before the edges are built
    with pytest.raises(ValueError):
        LS.create_from_triangle_mesh(o3d.geometry.TriangleMesh(np.zeros((3, 3)), np.array([[0, 1, 7]])))
