"""compute_convex_hull (PointCloud, TriangleMesh) and PointCloud.hidden_point_removal.

Reference numbers: tools/reference/record_python_round2.py (Open3D 0.20.0), on round2_data.make_inputs().
"""
import numpy as np
import pytest

import o3d
from round2_data import cube_corners, fp, make_cloud


def oriented_outward(mesh):
    """Every triangle's normal points away from the hull's centroid."""
    v = np.asarray(mesh.vertices)
    t = np.asarray(mesh.triangles)
    c = v.mean(axis=0)
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    return bool(np.all(np.einsum("ij,ij->i", n, v[t].mean(axis=1) - c) > 0))


def test_cube_hull_is_the_cube():
    rng = np.random.default_rng(3)
    inner = rng.uniform(0.1, 0.9, size=(40, 3))
    pts = np.vstack([inner[:20], cube_corners(), inner[20:]])  # corners at indices 20..27
    hull, idx = o3d.geometry.PointCloud(pts).compute_convex_hull()
    assert isinstance(hull, o3d.geometry.TriangleMesh) and isinstance(idx, list)
    assert sorted(idx) == list(range(20, 28))
    assert len(hull.vertices) == 8 and len(hull.triangles) == 12
    assert np.allclose(np.asarray(hull.vertices), pts[idx])
    assert hull.get_volume() == pytest.approx(1.0)
    assert hull.get_surface_area() == pytest.approx(6.0)
    assert oriented_outward(hull)


def test_cloud_hull_matches_open3d():
    hull, idx = make_cloud().compute_convex_hull()
    assert (len(hull.vertices), len(hull.triangles)) == (36, 68)  # Open3D 0.20
    assert sorted(idx) == [2, 5, 6, 10, 12, 22, 30, 32, 33, 37, 38, 53, 62, 64, 65, 69, 78, 88, 98, 106, 108, 109,
                           115, 123, 124, 125, 141, 161, 165, 185, 187, 191, 193, 194, 195, 198]
    assert hull.get_volume() == pytest.approx(37.72339079373836, rel=1e-9)
    assert hull.get_surface_area() == pytest.approx(68.30842518691156, rel=1e-9)
    assert oriented_outward(hull)


def test_mesh_hull():
    sphere = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=10)
    hull, idx = sphere.compute_convex_hull()
    assert (len(hull.vertices), len(hull.triangles)) == (182, 360)  # Open3D 0.20
    assert sorted(idx) == list(range(182))  # every vertex of a sphere is on its hull
    assert oriented_outward(hull)
    # Euler: a closed triangulated sphere has V - E + F = 2, so F = 2V - 4
    assert len(hull.triangles) == 2 * len(hull.vertices) - 4


def test_planar_needs_joggle():
    plane = np.column_stack([np.random.default_rng(2).uniform(-1, 1, (30, 2)), np.zeros(30)])
    pcd = o3d.geometry.PointCloud(plane)
    with pytest.raises(o3d.O3DError):
        pcd.compute_convex_hull()
    hull, idx = pcd.compute_convex_hull(joggle_inputs=True)
    assert len(hull.triangles) > 0 and all(0 <= i < 30 for i in idx)


def test_hidden_point_removal_sphere():
    sphere = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=10)
    pts = np.asarray(sphere.vertices)
    mesh, vis = o3d.geometry.PointCloud(pts).hidden_point_removal((0.0, 0.0, 5.0), 500.0)
    assert isinstance(mesh, o3d.geometry.TriangleMesh)
    assert len(vis) == 81 and fp(sorted(vis)) == 180440.0  # Open3D 0.20
    # analytic: a point of the unit sphere is visible from (0, 0, d) only when z >= 1 / d
    assert np.all(pts[vis][:, 2] >= 0.2 - 1e-9)
    hidden = np.setdiff1d(np.arange(len(pts)), vis)
    assert np.all(pts[hidden][:, 2] < 0.2 + 0.3)


def test_errors():
    with pytest.raises(ValueError):
        o3d.geometry.PointCloud().compute_convex_hull()
    with pytest.raises(ValueError):
        o3d.geometry.PointCloud(np.zeros((3, 3))).compute_convex_hull()
    with pytest.raises(ValueError):
        o3d.geometry.TriangleMesh().compute_convex_hull()
    pcd = make_cloud()
    with pytest.raises(ValueError):
        pcd.hidden_point_removal((0.0, 0.0, 5.0), 0.0)
    with pytest.raises(ValueError):
        pcd.hidden_point_removal((0.0, 0.0, np.nan), 10.0)
    with pytest.raises(ValueError):
        pcd.hidden_point_removal((0.0, 0.0), 10.0)
