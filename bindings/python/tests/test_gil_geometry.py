"""Long mesh and image calls release the GIL (as the point-cloud ones, see test_gil.py)."""
import numpy as np

import o3d
from test_gil import max_stall_during


def test_mesh_sampling_releases_gil():
    sphere = o3d.geometry.TriangleMesh.create_sphere(resolution=200)
    out = {}
    stall, duration = max_stall_during(
        lambda: out.setdefault("p", sphere.sample_points_uniformly(number_of_points=3_000_000, seed=1)))
    assert len(out["p"].points) == 3_000_000
    assert duration > 0.05, "sampling finished too fast to observe"
    assert stall < 0.5 * duration


def test_image_filter_releases_gil():
    img = o3d.geometry.Image(np.random.default_rng(0).uniform(size=(3000, 3000)).astype(np.float32))
    out = {}
    stall, duration = max_stall_during(
        lambda: out.setdefault("i", [img.filter(o3d.geometry.ImageFilterType.Gaussian7) for _ in range(3)]))
    assert np.asarray(out["i"][0]).shape == (3000, 3000)
    assert duration > 0.05
    assert stall < 0.5 * duration


def test_convex_hull_and_covariances_release_gil():
    pcd = o3d.geometry.PointCloud(np.random.default_rng(1).normal(size=(400_000, 3)))
    out = {}

    def work():
        out["hull"] = pcd.compute_convex_hull()
        pcd.estimate_covariances(o3d.geometry.KDTreeSearchParamKNN(knn=10))
        out["grid"] = o3d.geometry.VoxelGrid.create_from_point_cloud(pcd, 0.05)

    stall, duration = max_stall_during(work)
    assert len(out["hull"][1]) > 0 and pcd.has_covariances() and out["grid"].has_voxels()
    assert duration > 0.05
    assert stall < 0.5 * duration


def test_surface_reconstruction_releases_gil():
    from test_surface_reconstruction import oriented_sphere

    pcd = oriented_sphere(20_000)
    cube = o3d.geometry.PointCloud(np.random.default_rng(2).uniform(size=(20_000, 3)))
    out = {}

    def work():
        out["poisson"] = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=7)
        out["tetra"] = o3d.geometry.TetraMesh.create_from_point_cloud(cube)

    stall, duration = max_stall_during(work)
    assert len(out["poisson"][0].triangles) > 0 and len(out["tetra"][1]) == 20_000
    assert duration > 0.05
    assert stall < 0.5 * duration
