"""Open3D 0.20's mesh and point-cloud algorithms over index lists, boxes and ellipsoids: adjacency, non-manifold and
self-intersection queries, orient_triangles, filter_sharpen, create_ellipsoid, minimal boxes, bounding ellipsoids,
ARAP deformation, point-cloud smoothing, point covariances, planar patches and voxel_down_sample_and_trace.

Analytic answers, except where a test says its numbers come from the open3d 0.20 wheel.
"""
import copy

import numpy as np
import pytest

import o3d

G = o3d.geometry


def mesh_of(vertices, triangles):
    return G.TriangleMesh(np.asarray(vertices, dtype=np.float64), np.asarray(triangles, dtype=np.int32))


def rotation(axis, angle):
    axis = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


R0 = rotation((1.0, 2.0, 3.0), 0.7)


def directed_edges(tris):
    return [(int(t[k]), int(t[(k + 1) % 3])) for t in tris for k in range(3)]


# ---- TriangleMesh: topology ----------------------------------------------------------------------------------

def test_adjacency_list_of_a_tetrahedron():
    mesh = G.TriangleMesh.create_tetrahedron()
    assert not mesh.has_adjacency_list() and mesh.adjacency_list == []
    assert mesh.compute_adjacency_list() is mesh
    assert mesh.has_adjacency_list()
    assert mesh.adjacency_list == [{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}]
    assert copy.deepcopy(mesh).adjacency_list == mesh.adjacency_list  # copies keep it, as Open3D's
    mesh.adjacency_list = [[1], [0], [], []]
    assert mesh.adjacency_list == [{1}, {0}, set(), set()]
    with pytest.raises(ValueError):  # a triangle index out of range
        mesh_of([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 5]]).compute_adjacency_list()


def test_adjacency_list_skips_unused_vertices():
    mesh = mesh_of([[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5]], [[0, 1, 2]]).compute_adjacency_list()
    assert mesh.adjacency_list == [{1, 2}, {0, 2}, {0, 1}, set()]


def test_non_manifold_edges_and_vertices():
    # three triangles on edge (0, 1): non-manifold; the rest are boundary edges
    fin = mesh_of([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    edges = fin.get_non_manifold_edges()
    assert edges.dtype == np.int32 and edges.tolist() == [[0, 1]]
    assert len(fin.get_non_manifold_edges(allow_boundary_edges=False)) == 7
    closed = G.TriangleMesh.create_tetrahedron()
    assert closed.get_non_manifold_edges().shape == (0, 2)
    assert closed.get_non_manifold_edges(False).shape == (0, 2)
    # a bow tie: two triangles touching at vertex 2 only
    bowtie = mesh_of([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0, 2, 0], [1, 2, 0]], [[0, 1, 2], [2, 4, 3]])
    assert bowtie.get_non_manifold_vertices().tolist() == [2]
    assert closed.get_non_manifold_vertices().tolist() == []


def test_self_intersecting_triangles_and_is_intersecting():
    crossing = mesh_of([[0, 0, 0], [2, 0, 0], [1, 2, 0], [1, 1, -1], [1, 1, 1], [1, -1, 0.5]],
                       [[0, 1, 2], [3, 4, 5]])
    assert crossing.get_self_intersecting_triangles().tolist() == [[0, 1]]
    assert crossing.is_self_intersecting()
    box = G.TriangleMesh.create_box()
    assert box.get_self_intersecting_triangles().shape == (0, 2)
    other = G.TriangleMesh.create_box().translate((0.5, 0.5, 0.5))
    assert box.is_intersecting(other)
    assert not box.is_intersecting(G.TriangleMesh.create_box().translate((3.0, 0.0, 0.0)))


def test_orient_triangles():
    mesh = G.TriangleMesh.create_tetrahedron()
    tris = np.asarray(mesh.triangles).copy()
    flipped = tris.copy()
    flipped[2] = flipped[2][::-1]
    bad = mesh_of(np.asarray(mesh.vertices), flipped)
    assert len(set(directed_edges(flipped))) < 12
    assert bad.orient_triangles() is True
    fixed = np.asarray(bad.triangles)
    assert len(set(directed_edges(fixed))) == 12  # each shared edge walked once each way
    assert bad.get_volume() == pytest.approx(mesh.get_volume())
    assert G.TriangleMesh.create_mobius().orient_triangles() is False


# ---- TriangleMesh: filters, primitives, bounding volumes -------------------------------------------------------

def test_filter_sharpen_of_a_tetrahedron():
    # v' = v + s * sum over the 3 neighbours (v - n) = (1 + 4 s) v, as the centred tetrahedron sums to 0
    # (the open3d 0.20 wheel gives the same 3 * v for s = 0.5)
    mesh = G.TriangleMesh.create_tetrahedron()
    v = np.asarray(mesh.vertices).copy()
    out = mesh.filter_sharpen(number_of_iterations=1, strength=0.5)
    assert np.allclose(np.asarray(out.vertices), 3.0 * v)
    twice = mesh.filter_sharpen(2, 0.5, G.FilterScope.Vertex)
    assert np.allclose(np.asarray(twice.vertices), 9.0 * v)
    assert np.allclose(np.asarray(mesh.filter_sharpen(0).vertices), v)
    with pytest.raises(ValueError):
        mesh.filter_sharpen(-1)
    with pytest.raises(ValueError):
        mesh.filter_sharpen(1, float("nan"))


def test_create_ellipsoid():
    mesh = G.TriangleMesh.create_ellipsoid(3.0, 2.0, 1.0, 10)
    v = np.asarray(mesh.vertices)
    assert (len(v), len(mesh.triangles)) == (182, 360)  # as the open3d 0.20 wheel
    assert np.allclose((v / [3.0, 2.0, 1.0]) ** 2 @ np.ones(3), 1.0)
    assert mesh.is_watertight()
    assert 0.9 * 8 * np.pi < mesh.get_volume() < 8 * np.pi  # inscribed: a little less than 4/3 pi abc
    assert len(G.TriangleMesh.create_ellipsoid(create_uv_map=True).triangle_uvs) > 0
    for bad in ({"radius_x": 0.0}, {"radius_y": -1.0}, {"resolution": 1}):
        with pytest.raises(ValueError):
            G.TriangleMesh.create_ellipsoid(**bad)


def box_corners(extent, R=R0, center=(1.0, -2.0, 0.5)):
    e = np.asarray(extent) / 2.0
    local = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * e
    return local @ R.T + np.asarray(center)


def test_minimal_oriented_bounding_box_of_a_rotated_box():
    pts = box_corners((3.0, 2.0, 1.0))
    inner = np.random.default_rng(1).uniform(-0.4, 0.4, size=(30, 3)) @ R0.T + (1.0, -2.0, 0.5)
    pts = np.vstack([pts, inner])
    obb = G.OrientedBoundingBox.create_from_points_minimal(pts)
    assert isinstance(obb, G.OrientedBoundingBox)
    assert obb.volume() == pytest.approx(6.0, rel=1e-6)
    assert sorted(obb.extent) == pytest.approx([1.0, 2.0, 3.0], rel=1e-6)
    assert obb.center == pytest.approx([1.0, -2.0, 0.5])
    assert np.allclose(obb.R.T @ obb.R, np.eye(3)) and np.linalg.det(obb.R) == pytest.approx(1.0)
    cloud = G.PointCloud(pts)
    assert cloud.get_minimal_oriented_bounding_box().volume() == pytest.approx(6.0, rel=1e-6)
    assert cloud.get_minimal_oriented_bounding_box().volume() <= cloud.get_oriented_bounding_box().volume() + 1e-9
    mesh = G.TriangleMesh.create_box(3.0, 2.0, 1.0).rotate(R0)
    assert mesh.get_minimal_oriented_bounding_box().volume() == pytest.approx(6.0, rel=1e-6)


def test_minimal_oriented_bounding_box_errors():
    with pytest.raises(ValueError):
        G.OrientedBoundingBox.create_from_points_minimal(np.eye(3))  # fewer than 4 points
    flat = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.5, 0.5, 0]], dtype=float)
    with pytest.raises(ValueError):
        G.OrientedBoundingBox.create_from_points_minimal(flat)
    assert G.OrientedBoundingBox.create_from_points_minimal(flat, robust=True).volume() < 1e-3
    with pytest.raises(ValueError):
        G.PointCloud(np.zeros((2, 3))).get_minimal_oriented_bounding_box()
    with pytest.raises(ValueError):
        G.OrientedBoundingBox.create_from_points_minimal(np.zeros((4, 2)))


def ellipsoid_points(radii=(3.0, 2.0, 1.0), R=R0, center=(0.5, 1.0, -1.0), n=400):
    u = np.random.default_rng(7).normal(size=(n, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    return (u * radii) @ R.T + np.asarray(center)


def test_oriented_bounding_ellipsoid_recovers_a_sampled_ellipsoid():
    pts = ellipsoid_points()
    e = G.OrientedBoundingEllipsoid.create_from_points(pts)
    assert isinstance(e, G.OrientedBoundingEllipsoid)
    assert e.center == pytest.approx([0.5, 1.0, -1.0], abs=0.02)
    assert sorted(e.radii) == pytest.approx([1.0, 2.0, 3.0], rel=0.01)
    assert e.volume() == pytest.approx(4.0 / 3.0 * np.pi * 6.0, rel=0.02)
    assert np.allclose(e.R.T @ e.R, np.eye(3), atol=1e-9)
    local = (pts - e.center) @ e.R / e.radii  # every point inside, up to Open3D's tolerance
    assert np.all(np.linalg.norm(local, axis=1) <= 1.003)
    assert G.PointCloud(pts).get_oriented_bounding_ellipsoid().volume() == pytest.approx(e.volume())
    mesh = G.TriangleMesh.create_ellipsoid(3.0, 2.0, 1.0, 20)
    me = mesh.get_oriented_bounding_ellipsoid()
    assert sorted(me.radii) == pytest.approx([1.0, 2.0, 3.0], rel=0.01) and me.center == pytest.approx(0, abs=1e-6)
    with pytest.raises(ValueError):
        G.OrientedBoundingEllipsoid.create_from_points(np.eye(3))
    with pytest.raises(ValueError):  # a flat set has no ellipsoid, robust or not
        G.OrientedBoundingEllipsoid.create_from_points(np.c_[np.random.default_rng(0).random((20, 2)), np.zeros(20)],
                                                       robust=True)


def test_oriented_bounding_ellipsoid_value():
    e = G.OrientedBoundingEllipsoid()
    assert e.center.tolist() == [0, 0, 0] and e.R.tolist() == np.eye(3).tolist() and e.radii.tolist() == [0, 0, 0]
    assert e.volume() == 0.0 and e.is_empty()
    e = G.OrientedBoundingEllipsoid([1.0, 2.0, 3.0], np.eye(3), [1.0, 2.0, 3.0])
    assert e.volume() == pytest.approx(8 * np.pi) and e.get_center().tolist() == [1, 2, 3]
    assert e.get_min_bound().tolist() == [0, 0, 0] and e.get_max_bound().tolist() == [2, 4, 6]
    assert e.get_oriented_bounding_box().extent.tolist() == [2, 4, 6]
    c = G.OrientedBoundingEllipsoid(e)
    c.translate((1.0, 0.0, 0.0))
    assert e.center.tolist() == [1, 2, 3] and c.center.tolist() == [2, 2, 3]
    assert "OrientedBoundingEllipsoid" in repr(e)
    with pytest.raises(TypeError):
        G.OrientedBoundingEllipsoid([0.0, 0.0, 0.0])


def test_meshes_of_a_box_and_an_ellipsoid():
    obb = G.OrientedBoundingBox((1.0, -2.0, 0.5), R0, (3.0, 2.0, 1.0))
    mesh = G.TriangleMesh.create_from_oriented_bounding_box(obb)
    assert (len(mesh.vertices), len(mesh.triangles)) == (8, 12)
    corners = np.asarray(obb.get_box_points())
    assert sorted(map(tuple, np.round(np.asarray(mesh.vertices), 9))) == sorted(map(tuple, np.round(corners, 9)))
    # the open3d 0.20 wheel's vertex and triangle order (create_box's, not get_box_points')
    axis = G.TriangleMesh.create_from_oriented_bounding_box(G.OrientedBoundingBox((1.0, -2.0, 0.5), np.eye(3),
                                                                                   (3.0, 2.0, 1.0)))
    assert np.asarray(axis.vertices).tolist() == [[-0.5, -3, 0], [2.5, -3, 0], [-0.5, -3, 1], [2.5, -3, 1],
                                                  [-0.5, -1, 0], [2.5, -1, 0], [-0.5, -1, 1], [2.5, -1, 1]]
    assert np.asarray(axis.triangles).tolist() == [[4, 7, 5], [4, 6, 7], [0, 2, 4], [2, 6, 4], [0, 1, 2], [1, 3, 2],
                                                   [1, 5, 7], [1, 7, 3], [2, 3, 7], [2, 7, 6], [0, 4, 1], [1, 4, 5]]
    assert mesh.is_watertight() and mesh.get_volume() == pytest.approx(6.0)
    scaled = G.TriangleMesh.create_from_oriented_bounding_box(obb, scale=[2.0, 1.0, 0.5], create_uv_map=True)
    assert scaled.get_volume() == pytest.approx(6.0) and len(scaled.triangle_uvs) == 36
    assert scaled.get_center() == pytest.approx(obb.center)
    with pytest.raises(TypeError):
        G.TriangleMesh.create_from_oriented_bounding_box(G.AxisAlignedBoundingBox())
    with pytest.raises(ValueError):
        G.TriangleMesh.create_from_oriented_bounding_box(obb, scale=[0.0, 1.0, 1.0])

    e = G.OrientedBoundingEllipsoid((0.5, 1.0, -1.0), R0, (3.0, 2.0, 1.0))
    em = G.TriangleMesh.create_from_oriented_bounding_ellipsoid(e, resolution=10)
    local = (np.asarray(em.vertices) - e.center) @ e.R / e.radii
    assert len(local) == 182 and np.allclose(np.linalg.norm(local, axis=1), 1.0)
    assert np.allclose(np.asarray(em.vertex_colors), 1.0)  # painted white, as Open3D
    big = G.TriangleMesh.create_from_oriented_bounding_ellipsoid(e, scale=(2.0, 2.0, 2.0), resolution=10)
    assert big.get_volume() == pytest.approx(8.0 * em.get_volume())
    with pytest.raises(ValueError):
        G.TriangleMesh.create_from_oriented_bounding_ellipsoid(e, resolution=1)
    with pytest.raises(TypeError):
        G.TriangleMesh.create_from_oriented_bounding_ellipsoid(obb)


# ---- TriangleMesh: ARAP ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("energy", [G.DeformAsRigidAsPossibleEnergy.Spokes, G.DeformAsRigidAsPossibleEnergy.Smoothed])
def test_deform_as_rigid_as_possible_reproduces_a_rigid_motion(energy):
    mesh = G.TriangleMesh.create_sphere(1.0, 8)
    v = np.asarray(mesh.vertices).copy()
    R = rotation((0.0, 1.0, 1.0), 0.5)
    t = np.array([0.3, -0.2, 0.1])
    idx = list(range(0, len(v), 3))  # a third of the vertices constrained, as the C API test
    out = mesh.deform_as_rigid_as_possible(o3d.utility.IntVector(idx), o3d.utility.Vector3dVector(v[idx] @ R.T + t),
                                           max_iter=50, energy=energy, smoothed_alpha=0.01)
    assert isinstance(out, G.TriangleMesh) and len(out.triangles) == len(mesh.triangles)
    assert np.allclose(np.asarray(out.vertices), v @ R.T + t, atol=1e-3)
    assert np.allclose(np.asarray(mesh.vertices), v)  # the input is unchanged
    # max_iter 0 gives the input positions
    assert np.allclose(np.asarray(mesh.deform_as_rigid_as_possible(idx, v[idx], 0).vertices), v)


def test_deform_as_rigid_as_possible_errors():
    mesh = G.TriangleMesh.create_sphere(1.0, 5)
    v = np.asarray(mesh.vertices)
    with pytest.raises(ValueError):
        mesh.deform_as_rigid_as_possible([0, 1], v[:1], 5)  # lengths differ
    with pytest.raises(ValueError):
        mesh.deform_as_rigid_as_possible([len(v)], v[:1], 5)  # out of range
    with pytest.raises(ValueError):
        mesh.deform_as_rigid_as_possible([0, 0], v[:2], 5)  # repeated
    with pytest.raises(ValueError):
        mesh.deform_as_rigid_as_possible([], np.zeros((0, 3)), 5)  # no constraints
    with pytest.raises(ValueError):
        mesh.deform_as_rigid_as_possible([0], v[:1], -1)
    assert int(G.DeformAsRigidAsPossibleEnergy.Smoothed) == 1


# ---- PointCloud -------------------------------------------------------------------------------------------------

def noisy_plane(n=600, noise=0.01, seed=3):
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-1.0, 1.0, size=(n, 2))
    return np.c_[xy, rng.normal(0.0, noise, size=n)]


def test_smoothing_keeps_a_plane_and_flattens_noise():
    flat = noisy_plane(noise=0.0)
    pc = G.PointCloud(flat)
    for out in (pc.smooth_mls(G.KDTreeSearchParamHybrid(0.2, 30)), pc.smooth_mls(), pc.smooth_bilateral(),
                pc.smooth_laplacian(),
                pc.smooth_taubin(iterations=5, lambda_=0.5, mu=-0.53, knn=10),
                pc.smooth_bilateral(G.KDTreeSearchParamKNN(20), sigma_s=0.1, sigma_r=0.1)):
        assert isinstance(out, G.PointCloud) and len(out.points) == len(flat)
        assert np.allclose(np.asarray(out.points)[:, 2], 0.0, atol=1e-9)
    noisy = G.PointCloud(noisy_plane())
    z0 = np.asarray(noisy.points)[:, 2].std()
    assert np.asarray(noisy.smooth_mls(G.KDTreeSearchParamHybrid(0.2, 30)).points)[:, 2].std() < 0.5 * z0
    assert np.asarray(noisy.smooth_laplacian(5, 0.5, 10).points)[:, 2].std() < 0.5 * z0
    assert np.asarray(noisy.smooth_bilateral(G.KDTreeSearchParamKNN(30), 0.2, 0.05).points)[:, 2].std() < 0.8 * z0
    assert np.array_equal(np.asarray(noisy.smooth_laplacian(iterations=0).points), np.asarray(noisy.points))


def test_laplacian_step_is_analytic():
    # 3 points on a line, knn 2: each moves lambda of the way to the mean of the other two
    pts = np.array([[0.0, 0, 0], [1.0, 0, 0], [3.0, 0, 0]])
    out = np.asarray(G.PointCloud(pts).smooth_laplacian(iterations=1, lambda_=0.5, knn=2).points)
    assert out[:, 0] == pytest.approx([0 + 0.5 * 2.0, 1 + 0.5 * (1.5 - 1), 3 + 0.5 * (0.5 - 3)])


def test_smoothing_errors():
    pc = G.PointCloud(noisy_plane(50))
    with pytest.raises(ValueError):
        pc.smooth_laplacian(knn=0)
    with pytest.raises(ValueError):
        pc.smooth_taubin(iterations=-1)
    with pytest.raises(ValueError):
        pc.smooth_bilateral(sigma_s=0.0)
    with pytest.raises(ValueError):
        pc.smooth_mls(G.KDTreeSearchParamKNN(0))
    with pytest.raises(ValueError):
        pc.smooth_mls("knn")


def test_estimate_point_covariances_with_every_point_as_neighbour():
    pts = np.random.default_rng(5).normal(size=(12, 3)) * [1.0, 2.0, 0.5]
    pc = G.PointCloud(pts)
    cov = G.PointCloud.estimate_point_covariances(pc, G.KDTreeSearchParamKNN(12))
    assert cov.shape == (12, 3, 3)
    expected = np.cov(pts.T, bias=True)  # divided by the count, as Open3D
    assert np.allclose(cov, expected)
    assert not pc.has_covariances()  # the cloud is unchanged
    default = G.PointCloud.estimate_point_covariances(input=pc)  # KNN 30 >= 12 points: the same
    assert np.allclose(default, expected)
    few = G.PointCloud.estimate_point_covariances(G.PointCloud(pts[:2]))
    assert np.allclose(few, np.eye(3))  # fewer than 3 neighbours: the identity
    with pytest.raises(ValueError):
        G.PointCloud.estimate_point_covariances(pc, G.KDTreeSearchParamKNN(0))
    with pytest.raises(ValueError):
        G.PointCloud.estimate_point_covariances(pc, num_threads=-1)


def test_detect_planar_patches_on_two_planes():
    rng = np.random.default_rng(11)
    a = np.c_[rng.uniform(0, 1, 1500), rng.uniform(0, 1, 1500), np.zeros(1500)]
    b = np.c_[np.full(1000, 2.0), rng.uniform(0, 1, 1000), rng.uniform(0, 1, 1000)]
    pc = G.PointCloud(np.vstack([a, b]))
    pc.normals = np.vstack([np.tile([0.0, 0.0, 1.0], (1500, 1)), np.tile([1.0, 0.0, 0.0], (1000, 1))])
    patches = pc.detect_planar_patches()
    assert len(patches) == 2 and all(isinstance(p, G.OrientedBoundingBox) for p in patches)
    first, second = patches  # largest first
    assert abs(first.R[:, 2] @ [0, 0, 1]) == pytest.approx(1.0, abs=1e-3)
    assert abs(second.R[:, 2] @ [1, 0, 0]) == pytest.approx(1.0, abs=1e-3)
    assert first.center[:2] == pytest.approx([0.5, 0.5], abs=0.05) and first.center[2] == pytest.approx(0, abs=1e-6)
    assert second.center[0] == pytest.approx(2.0, abs=1e-6)
    same = pc.detect_planar_patches(60.0, 75.0, 0.75, 0.0, 0, G.KDTreeSearchParamKNN(30), num_threads=1)
    assert [p.center.tolist() for p in same] == [p.center.tolist() for p in patches]
    with pytest.raises(ValueError):
        G.PointCloud(a).detect_planar_patches()  # no normals
    with pytest.raises(ValueError):
        pc.detect_planar_patches(outlier_ratio=1.5)


def test_voxel_down_sample_and_trace():
    # the open3d 0.20 wheel gives the same voxels (in its own order): [3] -> cubic id 2, [2] -> 5, [0, 1] -> 0
    pts = np.array([[0.1, 0.1, 0.1], [0.2, 0.2, 0.2], [1.7, 0.2, 0.8], [0.3, 1.6, 0.1]])
    pc = G.PointCloud(pts)
    pc.colors = np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], [1.0, 1.0, 1.0]])
    down, cubic_id, traced = pc.voxel_down_sample_and_trace(1.0, [0, 0, 0], [2, 2, 2])
    assert isinstance(down, G.PointCloud)
    # sorted by voxel (z, y, x): (0,0,0), (1,0,0), (0,1,0)
    assert np.allclose(np.asarray(down.points), [[0.15, 0.15, 0.15], [1.7, 0.2, 0.8], [0.3, 1.6, 0.1]])
    assert np.allclose(np.asarray(down.colors)[0], [0.5, 0.5, 0.0])
    assert cubic_id.dtype == np.int32 and cubic_id.shape == (3, 8)
    expected = np.full((3, 8), -1)
    expected[0, 0], expected[1, 5], expected[2, 2] = 1, 2, 3
    assert cubic_id.tolist() == expected.tolist()
    assert isinstance(traced, list) and [t.tolist() for t in traced] == [[0, 1], [2], [3]]
    with pytest.raises(ValueError):
        pc.voxel_down_sample_and_trace(0.0, [0, 0, 0], [2, 2, 2])
    with pytest.raises(ValueError):
        pc.voxel_down_sample_and_trace(1.0, [0, 0, 0], [-1, 2, 2])  # max below min


def test_long_calls_release_the_gil():
    from test_gil import max_stall_during

    pc = G.PointCloud(np.random.default_rng(2).normal(size=(150_000, 3)))
    sphere = G.TriangleMesh.create_sphere(1.0, 60)
    out = {}

    def work():
        out["mls"] = pc.smooth_mls(G.KDTreeSearchParamKNN(10))
        out["cov"] = G.PointCloud.estimate_point_covariances(pc, G.KDTreeSearchParamKNN(10))
        out["self"] = sphere.get_self_intersecting_triangles()

    stall, duration = max_stall_during(work)
    assert len(out["mls"].points) == 150_000 and out["cov"].shape == (150_000, 3, 3) and len(out["self"]) == 0
    assert duration > 0.05
    assert stall < 0.5 * duration
