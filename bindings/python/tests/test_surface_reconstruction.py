"""TriangleMesh.create_from_point_cloud_poisson / _ball_pivoting / _alpha_shape: analytic results on sphere
samplings (radius, area, volume), the convex hull as the limit of alpha shapes, progress, cancel and errors."""
import _thread

import numpy as np
import pytest

import o3d

TriangleMesh = o3d.geometry.TriangleMesh


def fibonacci_sphere(n, radius=1.0):
    """n nearly evenly spaced points on a sphere about the origin, and their outward unit normals."""
    i = np.arange(n) + 0.5
    z = 1.0 - 2.0 * i / n
    r = np.sqrt(1.0 - z * z)
    phi = np.pi * (3.0 - np.sqrt(5.0)) * i
    normals = np.column_stack([r * np.cos(phi), r * np.sin(phi), z])
    return radius * normals, normals


def oriented_sphere(n, radius=1.0):
    points, normals = fibonacci_sphere(n, radius)
    pcd = o3d.geometry.PointCloud(points)
    pcd.normals = normals
    return pcd


def outward(mesh):
    """Whether every triangle's normal points away from the origin (the sphere's center)."""
    v = np.asarray(mesh.vertices)
    t = np.asarray(mesh.triangles)
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    return bool(np.all(np.einsum("ij,ij->i", n, v[t].mean(axis=1)) > 0))


# ---- Poisson

def test_poisson_sphere_is_watertight_at_the_radius():
    radius = 2.0
    mesh, densities = TriangleMesh.create_from_point_cloud_poisson(oriented_sphere(3000, radius), depth=6)
    assert isinstance(mesh, TriangleMesh) and isinstance(densities, o3d.utility.DoubleVector)
    v = np.asarray(mesh.vertices)
    assert len(v) > 500 and len(mesh.triangles) > 1000
    dist = np.linalg.norm(v, axis=1)
    assert abs(np.median(dist) - radius) < 0.02 * radius
    assert np.all(np.abs(dist - radius) < 0.1 * radius)
    assert mesh.is_watertight()
    assert mesh.get_volume() == pytest.approx(4.0 / 3.0 * np.pi * radius ** 3, rel=0.05)
    # densities: one octree depth per vertex, at most the requested depth
    d = np.asarray(densities)
    assert d.dtype == np.float64 and d.shape == (len(v),)
    assert np.all(np.isfinite(d)) and d.max() <= 6.0 + 1e-9 and d.min() > 0.0


def test_poisson_keywords_and_defaults():
    pcd = oriented_sphere(1500)
    coarse, _ = TriangleMesh.create_from_point_cloud_poisson(pcd, depth=4)
    fine, _ = TriangleMesh.create_from_point_cloud_poisson(pcd, 6, 0, 1.1, False, -1)
    assert len(fine.vertices) > 2 * len(coarse.vertices)  # depth sets the resolution
    same, _ = TriangleMesh.create_from_point_cloud_poisson(pcd, depth=6, n_threads=1)
    np.testing.assert_array_equal(np.asarray(same.vertices), np.asarray(fine.vertices))  # threads change nothing
    default, dens = TriangleMesh.create_from_point_cloud_poisson(pcd)  # Open3D's depth 8
    assert len(default.vertices) > len(fine.vertices) and len(dens) == len(default.vertices)
    linear, _ = TriangleMesh.create_from_point_cloud_poisson(pcd, depth=6, linear_fit=True)
    assert linear.is_watertight()


def test_poisson_carries_colors():
    pcd = oriented_sphere(2000)
    pcd.paint_uniform_color([0.2, 0.4, 0.6])
    mesh, _ = TriangleMesh.create_from_point_cloud_poisson(pcd, depth=5)
    assert mesh.has_vertex_colors()
    np.testing.assert_allclose(np.asarray(mesh.vertex_colors), np.tile([0.2, 0.4, 0.6], (len(mesh.vertices), 1)),
                               atol=1e-6)


def test_poisson_errors():
    no_normals = o3d.geometry.PointCloud(fibonacci_sphere(500)[0])
    with pytest.raises(o3d.InvalidArgumentError, match="normal"):
        TriangleMesh.create_from_point_cloud_poisson(no_normals)
    with pytest.raises(ValueError):
        TriangleMesh.create_from_point_cloud_poisson(o3d.geometry.PointCloud())
    pcd = oriented_sphere(500)
    for kwargs in ({"depth": 0}, {"depth": 17}, {"scale": 0.0}, {"width": -1.0}):
        with pytest.raises(o3d.InvalidArgumentError):
            TriangleMesh.create_from_point_cloud_poisson(pcd, **kwargs)
    with pytest.raises(o3d.UnsupportedError, match="point_weight"):
        TriangleMesh.create_from_point_cloud_poisson(pcd, point_weight=4.0)
    TriangleMesh.create_from_point_cloud_poisson(pcd, depth=4, full_depth=5, samples_per_node=1.5, point_weight=2.0)
    with pytest.raises(TypeError):
        TriangleMesh.create_from_point_cloud_poisson(None)
    bad = oriented_sphere(500)
    np.asarray(bad.points)[7] = np.nan
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_poisson(bad)


def test_poisson_progress_cancel_and_callback_errors(capsys):
    pcd = oriented_sphere(1000)
    seen = []
    TriangleMesh.create_from_point_cloud_poisson(pcd, depth=5, callback=seen.append)
    assert seen and all(0.0 <= f <= 1.0 for f in seen) and seen == sorted(seen)
    calls = []
    with pytest.raises(o3d.CancelledError):
        TriangleMesh.create_from_point_cloud_poisson(pcd, depth=5, callback=lambda f: calls.append(f) or True)
    assert len(calls) == 1

    class Stop(Exception):
        pass

    def boom(fraction):
        raise Stop()

    with pytest.raises(Stop):
        TriangleMesh.create_from_point_cloud_poisson(pcd, depth=5, callback=boom)
    TriangleMesh.create_from_point_cloud_poisson(pcd, depth=5, print_progress=True)
    err = capsys.readouterr().err
    assert "Poisson" in err and "%" in err


def test_poisson_ctrl_c_interrupts():
    calls = []

    def press_ctrl_c(fraction):
        calls.append(fraction)
        if len(calls) == 1:
            _thread.interrupt_main()  # as Ctrl-C: the pending signal is seen at the next progress report
        return False

    with pytest.raises(KeyboardInterrupt):
        TriangleMesh.create_from_point_cloud_poisson(oriented_sphere(2000), depth=6, callback=press_ctrl_c)
    assert len(calls) <= 2


# ---- ball pivoting

def test_ball_pivoting_sphere_area_and_vertices():
    pcd = oriented_sphere(3000)
    spacing = np.sqrt(4.0 * np.pi / 3000)
    mesh = TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, o3d.utility.DoubleVector([spacing, 2 * spacing]))
    # the vertices are the input points, with their normals
    np.testing.assert_array_equal(np.asarray(mesh.vertices), np.asarray(pcd.points))
    np.testing.assert_array_equal(np.asarray(mesh.vertex_normals), np.asarray(pcd.normals))
    assert len(mesh.triangles) > 0.9 * 2 * 3000  # a closed sphere has 2V - 4 triangles
    assert mesh.get_surface_area() == pytest.approx(4.0 * np.pi, rel=0.05)
    assert outward(mesh)  # wound to agree with the normals
    # radii as a list or an array give the same mesh
    for radii in ([spacing, 2 * spacing], np.array([spacing, 2 * spacing])):
        again = TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, radii)
        np.testing.assert_array_equal(np.asarray(again.triangles), np.asarray(mesh.triangles))


def test_ball_pivoting_small_ball_finds_nothing():
    pcd = oriented_sphere(500)
    mesh = TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, [1e-4])
    assert len(mesh.triangles) == 0 and len(mesh.vertices) == 500


def test_ball_pivoting_errors_and_cancel():
    pcd = oriented_sphere(500)
    for radii in ([-0.1], [0.0], [], [np.nan], [0.1, -0.2]):
        with pytest.raises(o3d.InvalidArgumentError):
            TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, radii)
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, None)
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, [[0.1, 0.2]])  # not 1-D
    with pytest.raises(o3d.InvalidArgumentError, match="normal"):
        TriangleMesh.create_from_point_cloud_ball_pivoting(o3d.geometry.PointCloud(fibonacci_sphere(500)[0]), [0.2])
    with pytest.raises(o3d.CancelledError):
        TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, [0.2], callback=lambda f: True)


# ---- alpha shapes

def test_alpha_shape_with_huge_alpha_is_the_convex_hull():
    rng = np.random.default_rng(7)
    points = fibonacci_sphere(300)[0] + rng.uniform(-0.01, 0.01, size=(300, 3))
    inner = rng.uniform(-0.4, 0.4, size=(100, 3))
    pcd = o3d.geometry.PointCloud(np.vstack([points, inner]))
    shape = TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1000.0)
    hull, hull_idx = pcd.compute_convex_hull()
    assert len(shape.triangles) == len(hull.triangles)
    assert shape.get_volume() == pytest.approx(hull.get_volume(), rel=1e-9)
    assert shape.get_surface_area() == pytest.approx(hull.get_surface_area(), rel=1e-9)
    used = np.unique(np.asarray(shape.triangles))
    np.testing.assert_array_equal(np.unique(np.asarray(shape.vertices)[used], axis=0),
                                  np.unique(np.asarray(pcd.points)[hull_idx], axis=0))
    assert outward(shape)


def test_alpha_shape_reuses_a_tetra_mesh_and_shrinks_with_alpha():
    rng = np.random.default_rng(8)
    pcd = o3d.geometry.PointCloud(rng.uniform(-1.0, 1.0, size=(400, 3)))
    hull, _ = pcd.compute_convex_hull()
    tetra_mesh, pt_map = o3d.geometry.TetraMesh.create_from_point_cloud(pcd)
    volumes = []
    for alpha in (1000.0, 10.0, 2.0, 1.0, 0.5):
        fresh = TriangleMesh.create_from_point_cloud_alpha_shape(pcd, alpha)
        reused = TriangleMesh.create_from_point_cloud_alpha_shape(pcd, alpha, tetra_mesh, pt_map)
        np.testing.assert_array_equal(np.asarray(reused.triangles), np.asarray(fresh.triangles))
        np.testing.assert_array_equal(np.asarray(reused.vertices), np.asarray(fresh.vertices))
        assert fresh.is_watertight()
        volumes.append(fresh.get_volume())
    assert volumes[0] == pytest.approx(hull.get_volume(), rel=1e-9)
    assert all(a > b for a, b in zip(volumes, volumes[1:]))  # a smaller ball carves more away
    tiny = TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1e-3)  # no tetrahedron is that small
    assert len(tiny.triangles) == 0
    # pt_map as an IntVector or an array works as the list
    for pt_map_like in (o3d.utility.IntVector(pt_map), np.array(pt_map)):
        again = TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1000.0, tetra_mesh, pt_map_like)
        assert again.get_volume() == pytest.approx(volumes[0], rel=1e-12)


def test_alpha_shape_errors():
    rng = np.random.default_rng(9)
    pcd = o3d.geometry.PointCloud(rng.uniform(size=(50, 3)))
    for alpha in (0.0, -1.0, np.nan, np.inf):
        with pytest.raises(o3d.InvalidArgumentError):
            TriangleMesh.create_from_point_cloud_alpha_shape(pcd, alpha)
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_alpha_shape(o3d.geometry.PointCloud(rng.uniform(size=(3, 3))), 1.0)
    flat = o3d.geometry.PointCloud(np.column_stack([rng.uniform(size=(20, 2)), np.zeros(20)]))
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_alpha_shape(flat, 1.0)
    tetra_mesh, pt_map = o3d.geometry.TetraMesh.create_from_point_cloud(pcd)
    with pytest.raises(o3d.InvalidArgumentError, match="pt_map"):
        TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1.0, tetra_mesh)
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1.0, tetra_mesh, pt_map[:-1])  # one short
    with pytest.raises(o3d.InvalidArgumentError):
        TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1.0, tetra_mesh, [999] * len(pt_map))
    with pytest.raises(o3d.InvalidArgumentError, match="tetra_mesh"):
        TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1.0, "not a mesh", pt_map)
    with pytest.raises(o3d.CancelledError):
        TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 1.0, callback=lambda f: True)
