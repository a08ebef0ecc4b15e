"""TriangleMesh primitives and processing, compared with Open3D 0.20.

Reference numbers: tools/reference/record_python_geometry.py (run with /tmp/o3dref/bin/python).
fp(a) = sum_i (i + 1) * a_i over the flattened array, so vertex/triangle order and values must match.
"""
import numpy as np
import pytest

import o3d

TM = o3d.geometry.TriangleMesh
PHI = (1 + 5**0.5) / 2


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def check(mesh, counts, area, fp_vertices=None, fp_triangles=None, rel=1e-9):
    assert (len(mesh.vertices), len(mesh.triangles)) == counts
    assert mesh.get_surface_area() == pytest.approx(area, rel=rel)
    if fp_vertices is not None:
        assert fp(mesh.vertices) == pytest.approx(fp_vertices, rel=rel, abs=1e-6)
    if fp_triangles is not None:
        assert fp(mesh.triangles) == pytest.approx(fp_triangles, rel=0, abs=0.5)


# name, factory, (vertices, triangles), area, fp(vertices), fp(triangles) -- Open3D 0.20.0
PRIMITIVES = [
    ("sphere", lambda: TM.create_sphere(), (762, 1520), 12.501878921475342, -352326.56372623815, 5083286400.0),
    ("tetrahedron", lambda: TM.create_tetrahedron(), (4, 4), 4.618802153517006, -0.6921304299024627, 137.0),
    ("octahedron", lambda: TM.create_octahedron(), (6, 8), 6.928203230275508, -27.0, 858.0),
    # Open3D's icosahedron puts its vertices at radius * sqrt(1 + phi^2), not on the sphere of `radius`; the
    # header's contract is "inscribed in a sphere of radius": same layout, Open3D's numbers scaled to it.
    ("icosahedron", lambda: TM.create_icosahedron(), (12, 20), 34.64101615137755 / (1 + PHI**2),
     -19.41640786499874 / np.sqrt(1 + PHI**2), 11084.0),
    ("torus", lambda: TM.create_torus(), (600, 1200), 19.56851568284109, -192099.74835761043, 2526554700.0),
    ("cylinder", lambda: TM.create_cylinder(), (102, 200), 18.69509709071738, -7100.062727201258, 10703860.0),
    ("cone", lambda: TM.create_cone(), (22, 40), 10.068990563677295, -207.41254544025136, 71020.0),
    ("arrow", lambda: TM.create_arrow(), (124, 240), 64.43849822000266, 61666.81845463836, 19423400.0),
    ("frame", lambda: TM.create_coordinate_frame(), (1134, 2240), 0.7441863985758009, 475679.12033189036,
     16730596680.0),
]


@pytest.mark.parametrize("name,make,counts,area,fpv,fpt", PRIMITIVES, ids=[p[0] for p in PRIMITIVES])
def test_primitives_match_open3d(name, make, counts, area, fpv, fpt):
    check(make(), counts, area, fpv, fpt)


def test_regular_solids_are_inscribed_in_radius():
    for make in (TM.create_tetrahedron, TM.create_octahedron, TM.create_icosahedron):
        v = np.asarray(make(radius=2.0).vertices)
        np.testing.assert_allclose(np.linalg.norm(v, axis=1), 2.0)


def test_primitive_keywords_and_errors():
    box = TM.create_box(width=1.0, height=2.0, depth=3.0)
    assert box.get_volume() == pytest.approx(6.0)
    assert TM.create_torus().euler_poincare_characteristic() == 0  # Open3D 0.20: 0
    frame = TM.create_coordinate_frame(size=2.0, origin=[1, 2, 3])
    assert frame.has_vertex_colors()
    with pytest.raises(NotImplementedError):
        TM.create_box(create_uv_map=True)
    with pytest.raises(ValueError):
        TM.create_sphere(radius=-1.0)
    with pytest.raises(ValueError):
        TM.create_sphere(resolution=0)


def test_create_mobius():
    m = TM.create_mobius()  # Open3D's defaults: length_split=70, width_split=15, twists=1
    assert len(m.vertices) == 70 * 15
    assert len(m.triangles) == 2 * 70 * 14
    assert m.euler_poincare_characteristic() == 0
    assert not m.is_orientable()
    assert m.is_edge_manifold() and m.is_vertex_manifold()
    band = TM.create_mobius(length_split=20, width_split=4, twists=2)
    assert (len(band.vertices), len(band.triangles)) == (80, 120)
    assert band.euler_poincare_characteristic() == 0
    assert band.is_orientable()
    # Open3D's keyword is spelt `raidus`; it scales the centre circle (with width 0.5 the band spans 2 +- 0.25).
    wide = TM.create_mobius(raidus=2.0, width=0.5, flatness=0.0)
    r = np.linalg.norm(np.asarray(wide.vertices)[:, :2], axis=1)
    assert r.min() == pytest.approx(1.75) and r.max() == pytest.approx(2.25)
    np.testing.assert_allclose(np.asarray(wide.vertices)[:, 2], 0.0)
    for bad in (dict(length_split=2), dict(width_split=1), dict(twists=-1), dict(raidus=0.0), dict(width=-1.0),
                dict(scale=0.0), dict(flatness=float("nan"))):
        with pytest.raises(ValueError):
            TM.create_mobius(**bad)
    with pytest.raises(TypeError):
        TM.create_mobius(radius=1.0)  # Open3D has no `radius` keyword here


def test_subdivision_matches_open3d():
    check(TM.create_tetrahedron().subdivide_midpoint(number_of_iterations=1), (10, 16), 4.618802153517008,
          9.860783840712665, 6825.0)
    check(TM.create_octahedron().subdivide_loop(number_of_iterations=1), (18, 32), 3.2935254936674268, -68.625,
          48760.0)


def test_smoothing_matches_open3d():
    base = TM.create_octahedron().subdivide_midpoint(2)
    check(base.filter_smooth_simple(number_of_iterations=2), (66, 128), 4.228484228726591, -855.1873469387754,
          2870093.0)
    check(base.filter_smooth_laplacian(number_of_iterations=3, lambda_filter=0.5), (66, 128), 4.488455029012601,
          -876.112745831577, 2870093.0)
    check(base.filter_smooth_taubin(number_of_iterations=5), (66, 128), 6.224471413827657, -1036.6202027660684,
          2870093.0)
    # scope: smoothing only colors leaves the vertices alone
    colored = TM(base)
    colored.vertex_colors = np.random.default_rng(1).uniform(size=(66, 3))
    out = colored.filter_smooth_simple(filter_scope=o3d.geometry.FilterScope.Color)
    np.testing.assert_array_equal(np.asarray(out.vertices), np.asarray(base.vertices))
    assert not np.allclose(np.asarray(out.vertex_colors), np.asarray(colored.vertex_colors))


def test_simplification():
    sphere = TM.create_sphere()
    vc = sphere.simplify_vertex_clustering(voxel_size=0.5)
    # Open3D 0.20: (74, 144), area 11.682139562979291
    assert (len(vc.vertices), len(vc.triangles)) == (74, 144)
    assert vc.get_surface_area() == pytest.approx(11.682139562979291, rel=1e-9)
    q = sphere.simplify_vertex_clustering(0.5, o3d.geometry.SimplificationContraction.Quadric)
    assert len(q.triangles) == 144
    dec = sphere.simplify_quadric_decimation(target_number_of_triangles=200)
    assert 0 < len(dec.triangles) <= 200
    assert dec.get_surface_area() == pytest.approx(sphere.get_surface_area(), rel=0.05)
    assert len(sphere.triangles) == 1520  # the input is unchanged
    with pytest.raises(ValueError):
        sphere.simplify_vertex_clustering(voxel_size=0.0)


def test_crop_matches_open3d():
    box = TM.create_box().subdivide_midpoint(2)
    out = box.crop(o3d.geometry.AxisAlignedBoundingBox((-1, -1, -1), (1, 1, 0.5)))
    check(out, (57, 96), 3.0, 5814.0, 1406643.0)
    with pytest.raises(TypeError):
        box.crop(None)


def test_sample_points_uniformly_on_box():
    box = TM.create_box()
    pcd = box.sample_points_uniformly(number_of_points=500, seed=7)
    pts = np.asarray(pcd.points)
    assert pts.shape == (500, 3)
    # every point lies on a face: one coordinate is 0 or 1, all within [0, 1]
    assert np.all((pts >= -1e-12) & (pts <= 1 + 1e-12))
    on_face = np.any(np.isclose(pts, 0.0, atol=1e-12) | np.isclose(pts, 1.0, atol=1e-12), axis=1)
    assert on_face.all()
    # area-weighted: each of the six faces gets about 1/6 of the points
    again = box.sample_points_uniformly(number_of_points=500, seed=7)
    np.testing.assert_array_equal(np.asarray(again.points), pts)
    default = box.sample_points_uniformly()
    assert len(default.points) == 100  # Open3D's default number_of_points
    with_normals = box.compute_vertex_normals().sample_points_uniformly(50, use_triangle_normal=True, seed=1)
    n = np.asarray(with_normals.normals)
    np.testing.assert_allclose(np.abs(n).max(axis=1), 1.0)  # axis-aligned face normals


def test_sample_points_poisson_disk():
    sphere = TM.create_sphere()
    pcd = sphere.sample_points_poisson_disk(number_of_points=200, seed=3)
    pts = np.asarray(pcd.points)
    assert pts.shape == (200, 3)
    np.testing.assert_allclose(np.linalg.norm(pts, axis=1), 1.0, atol=0.02)
    # better spread than uniform samples: the closest pair is not very close
    d = np.linalg.norm(pts[:, None, :] - pts[None, :, :], axis=2) + np.eye(200) * 10
    assert d.min() > 0.05
    with pytest.raises(NotImplementedError):
        sphere.sample_points_poisson_disk(10, pcl=o3d.geometry.PointCloud())
    with pytest.raises(ValueError):
        sphere.sample_points_uniformly(-1)
