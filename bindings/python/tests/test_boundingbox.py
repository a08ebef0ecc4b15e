"""OrientedBoundingBox, AxisAlignedBoundingBox corners / indices, get_oriented_bounding_box, crop by boxes.

Reference numbers: tools/reference/record_python_round2.py (Open3D 0.20.0), on round2_data.make_inputs().
"""
import numpy as np
import pytest

import o3d
from round2_data import cube_corners, fp, make_cloud, make_inputs, rot_xyz

OBB = o3d.geometry.OrientedBoundingBox
AABB = o3d.geometry.AxisAlignedBoundingBox

# Open3D 0.20: AxisAlignedBoundingBox((-1,-2,-3),(1,2,3)).get_box_points() (also the OBB made from it)
AABB_POINTS = [[-1.0, -2.0, -3.0], [1.0, -2.0, -3.0], [-1.0, 2.0, -3.0], [-1.0, -2.0, 3.0], [1.0, 2.0, 3.0],
               [-1.0, 2.0, 3.0], [1.0, -2.0, 3.0], [1.0, 2.0, -3.0]]
# Open3D 0.20: OrientedBoundingBox((1,2,3), R_xyz(0.3,-0.2,0.5), (2,1,0.5)).get_box_points()
GIVEN_POINTS = [[0.42451246796847564, 1.2326511836611174, 2.373509860780251],
                [2.1446911443785703, 2.0456294538334894, 2.9899931561350828],
                [-0.045356478981039644, 2.0991852849792685, 2.541860162072818],
                [0.3251778025709451, 1.0878364448483595, 2.84165654257235],
                [1.5754875320315245, 2.7673488163388824, 3.626490139219749],
                [-0.14469114437857025, 1.9543705461665106, 3.0100068438649172],
                [2.0453564789810397, 1.9008147150207315, 3.458139837927182],
                [1.6748221974290551, 2.9121635551516403, 3.15834345742765]]


def given_box():
    return OBB((1.0, 2.0, 3.0), rot_xyz(0.3, -0.2, 0.5), (2.0, 1.0, 0.5))


def test_default_and_attributes():
    b = OBB()
    assert np.array_equal(b.center, np.zeros(3)) and np.array_equal(b.R, np.eye(3))
    assert np.array_equal(b.extent, np.zeros(3)) and np.array_equal(b.color, np.zeros(3))
    b = given_box()
    assert b.volume() == pytest.approx(1.0)
    assert np.allclose(b.get_center(), [1, 2, 3])
    copy = OBB(b)
    copy.center[0] = 9.0
    assert b.center[0] == 1.0


def test_box_points_match_open3d():
    assert np.allclose(np.asarray(given_box().get_box_points()), GIVEN_POINTS, atol=1e-12)
    b = given_box()
    assert np.allclose(b.get_min_bound(), np.min(GIVEN_POINTS, axis=0))
    assert np.allclose(b.get_max_bound(), np.max(GIVEN_POINTS, axis=0))
    aabb = AABB((-1, -2, -3), (1, 2, 3))
    assert np.array_equal(np.asarray(aabb.get_box_points()), AABB_POINTS)
    from_aabb = OBB.create_from_axis_aligned_bounding_box(aabb)
    assert np.allclose(from_aabb.R, np.eye(3)) and np.allclose(from_aabb.extent, [2, 4, 6])
    assert np.allclose(from_aabb.center, 0) and from_aabb.volume() == pytest.approx(48.0)
    assert np.array_equal(np.asarray(from_aabb.get_box_points()), AABB_POINTS)
    assert np.array_equal(np.asarray(aabb.get_oriented_bounding_box().get_box_points()), AABB_POINTS)


def test_create_from_points_rotated_cuboid():
    # The corners of a rotated 3 x 2 x 1 cuboid: the box is that cuboid (analytic).
    R = rot_xyz(0.4, 0.1, -0.7)
    corners = (cube_corners((-1.5, -1, -0.5), (1.5, 1, 0.5)) @ R.T) + [5.0, -1.0, 2.0]
    for pts in (corners, o3d.utility.Vector3dVector(corners)):
        b = OBB.create_from_points(pts)
        assert sorted(b.extent) == pytest.approx([1.0, 2.0, 3.0], abs=1e-9)
        assert np.allclose(b.center, [5.0, -1.0, 2.0])
        assert np.allclose(b.R.T @ b.R, np.eye(3))
        assert b.volume() == pytest.approx(6.0)
        assert len(b.get_point_indices_within_bounding_box(corners)) == 8


def test_cloud_obb_matches_open3d():
    pcd = make_cloud()
    b = pcd.get_oriented_bounding_box()
    assert isinstance(b, OBB)
    # Open3D 0.20: volume 48.3169533578426, sorted extent [2.02397847.., 3.99233333.., 5.97952737..]
    assert b.volume() == pytest.approx(48.3169533578426, rel=1e-9)
    assert sorted(b.extent) == pytest.approx([2.0239784715513656, 3.9923333335220432, 5.979527372509358], rel=1e-9)
    assert np.allclose(b.center, [0.009267446089504028, 0.03275970302178599, -0.012713786250773261], atol=1e-9)
    # every point lies in its own box (Open3D: 199 of 200, one lost to rounding on the boundary)
    assert len(b.get_point_indices_within_bounding_box(pcd.points)) >= 199
    robust = pcd.get_oriented_bounding_box(robust=True)
    assert robust.volume() == pytest.approx(48.31695335899216, rel=1e-6)


def test_planar_points_need_robust():
    plane = np.column_stack([np.random.default_rng(1).uniform(-1, 1, (50, 2)), np.zeros(50)])
    pcd = o3d.geometry.PointCloud(plane)
    with pytest.raises(o3d.O3DError):
        pcd.get_oriented_bounding_box()
    b = pcd.get_oriented_bounding_box(robust=True)
    assert b.volume() < 1e-3
    assert len(b.get_point_indices_within_bounding_box(plane)) >= 45


def test_point_indices_within_rotated_box_match_open3d():
    cloud, _ = make_inputs()
    box = OBB((0.0, 0.0, 0.0), rot_xyz(0.0, 0.0, 0.6), (3.0, 1.0, 1.0))
    expected = [20, 55, 74, 80, 83, 121, 142, 151, 158, 160, 176, 196]  # Open3D 0.20
    assert box.get_point_indices_within_bounding_box(cloud) == expected
    assert box.get_point_indices_within_bounding_box(o3d.utility.Vector3dVector(cloud)) == expected
    # same set by the box's own coordinates (analytic)
    local = np.abs(cloud @ box.R) <= box.extent / 2
    assert np.flatnonzero(local.all(axis=1)).tolist() == expected


def test_crop_by_oriented_box():
    pcd = make_cloud()
    box = OBB((0.0, 0.0, 0.0), rot_xyz(0.0, 0.0, 0.6), (3.0, 1.0, 1.0))
    kept = pcd.crop(box)
    assert len(kept.points) == 12
    assert fp(kept.points) == pytest.approx(-25.936335041180243, rel=1e-12)  # Open3D 0.20
    outside = pcd.crop(box, invert=True)
    assert len(outside.points) == 188
    # an axis-aligned box still crops as before
    assert len(pcd.crop(AABB((-1, -1, -1), (1, 1, 1))).points) == int(
        np.all(np.abs(np.asarray(pcd.points)) <= 1, axis=1).sum())


def test_mesh_obb_and_crop():
    mesh = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=10)
    assert mesh.get_oriented_bounding_box().volume() == pytest.approx(8.0, rel=1e-9)  # Open3D 0.20: 8.0
    box = OBB((0.0, 0.0, 0.0), rot_xyz(0.0, 0.0, 0.6), (3.0, 1.0, 1.0))
    cropped = mesh.crop(box)
    assert (len(cropped.vertices), len(cropped.triangles)) == (18, 16)  # Open3D 0.20
    local = np.abs(np.asarray(cropped.vertices) @ box.R) <= box.extent / 2 + 1e-12
    assert local.all()


def test_errors():
    with pytest.raises(ValueError):
        OBB.create_from_points(np.zeros((3, 3)))  # fewer than 4 points
    with pytest.raises(ValueError):
        OBB.create_from_points(np.zeros((5, 2)))
    with pytest.raises(ValueError):
        OBB.create_from_points([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, np.nan]])
    with pytest.raises(ValueError):
        given_box().get_point_indices_within_bounding_box(np.zeros((4, 4)))
    bad = given_box()
    bad.extent = np.array([1.0, -1.0, 1.0])
    with pytest.raises(ValueError):
        bad.get_box_points()
    with pytest.raises(ValueError):
        o3d.geometry.PointCloud().get_oriented_bounding_box()
    with pytest.raises(TypeError):
        make_cloud().crop("box")
    with pytest.raises(ValueError):
        o3d.geometry.TriangleMesh().get_oriented_bounding_box()
