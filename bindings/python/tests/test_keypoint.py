"""o3d.geometry.keypoint.compute_iss_keypoints: ISS keypoints of a box sampling sit on its edges, at every corner."""
import itertools

import numpy as np
import pytest

import o3d
from o3d.geometry import keypoint

SIZE = np.array([2.0, 1.0, 0.5])


def box_surface(step=0.05):
    """The surface of the box [0, SIZE] sampled on a regular grid of `step`, without repeats."""
    axes = [np.linspace(0.0, s, int(round(s / step)) + 1) for s in SIZE]
    grid = np.array(list(itertools.product(*axes)))
    on_face = np.any(np.isclose(grid, 0.0) | np.isclose(grid, SIZE), axis=1)
    return grid[on_face]


def test_keypoints_lie_on_the_edges_and_at_every_corner():
    points = box_surface()
    keys = keypoint.compute_iss_keypoints(o3d.geometry.PointCloud(points))  # radii from the cloud's resolution
    assert isinstance(keys, o3d.geometry.PointCloud)
    k = np.asarray(keys.points)
    assert 8 <= len(k) < 0.05 * len(points)
    # every corner has a keypoint next to it (Open3D 0.20: the same, 29 keypoints in all)
    corners = np.array(list(itertools.product(*[[0.0, s] for s in SIZE])))
    assert np.all(np.min(np.linalg.norm(corners[:, None, :] - k[None], axis=2), axis=1) < 0.08)
    # and every keypoint is on an edge of the box (two coordinates within a grid step of a face)
    to_faces = np.sort(np.minimum(k, SIZE - k), axis=1)
    assert np.all(to_faces[:, 1] < 0.05 + 1e-9)
    # keypoints are input points
    assert {tuple(p) for p in k} <= {tuple(p) for p in points}


def test_defaults_and_module_import():
    import o3d.geometry.keypoint as kp

    assert kp.compute_iss_keypoints is o3d.geometry.keypoint.compute_iss_keypoints
    pcd = o3d.geometry.PointCloud(box_surface())
    default = kp.compute_iss_keypoints(pcd)  # radii from the cloud's resolution
    assert len(default.points) < len(pcd.points)
    same = kp.compute_iss_keypoints(pcd, 0.0, 0.0, 0.975, 0.975, 5, num_threads=1)
    np.testing.assert_array_equal(np.asarray(same.points), np.asarray(default.points))
    # a stricter neighbour count drops every point
    assert len(kp.compute_iss_keypoints(pcd, 0.15, 0.15, min_neighbors=100000).points) == 0


def test_keypoints_carry_normals_and_colors():
    pcd = o3d.geometry.PointCloud(box_surface())
    pcd.estimate_normals()
    pcd.paint_uniform_color([0.1, 0.2, 0.3])
    keys = keypoint.compute_iss_keypoints(pcd, 0.15, 0.15)
    assert len(keys.points) > 0 and keys.has_normals() and keys.has_colors()
    np.testing.assert_allclose(np.asarray(keys.colors), np.tile([0.1, 0.2, 0.3], (len(keys.points), 1)))


def test_errors():
    pcd = o3d.geometry.PointCloud(box_surface())
    for kwargs in ({"salient_radius": -1.0}, {"non_max_radius": -1.0}, {"gamma_21": 0.0}, {"gamma_32": 1.5},
                   {"salient_radius": np.nan}):
        with pytest.raises(o3d.InvalidArgumentError):
            keypoint.compute_iss_keypoints(pcd, **kwargs)
    with pytest.raises(TypeError):
        keypoint.compute_iss_keypoints(None)
    bad = o3d.geometry.PointCloud(np.vstack([box_surface(), [[np.inf, 0.0, 0.0]]]))
    with pytest.raises(o3d.InvalidArgumentError):
        keypoint.compute_iss_keypoints(bad)
