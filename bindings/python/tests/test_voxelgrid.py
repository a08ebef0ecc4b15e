"""o3d.geometry.VoxelGrid from clouds and meshes, get_voxels / get_voxel / check_if_included.

Reference numbers: tools/reference/record_python_round2.py (Open3D 0.20.0), on round2_data.make_inputs().
Voxels come sorted by grid index; the Open3D values were recorded after sorting Open3D's (hash) order.
"""
import numpy as np
import pytest

import o3d
from round2_data import fp, make_cloud, make_inputs

VG = o3d.geometry.VoxelGrid


def test_two_points_analytic():
    pcd = o3d.geometry.PointCloud(np.array([[0.0, 0, 0], [1.0, 0, 0], [1.1, 0, 0]]))
    pcd.colors = np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]])
    vg = VG.create_from_point_cloud(pcd, 0.5)
    assert vg.voxel_size == 0.5 and np.allclose(vg.origin, [-0.25, -0.25, -0.25])
    voxels = vg.get_voxels()
    assert all(isinstance(v, o3d.geometry.Voxel) for v in voxels)
    assert [v.grid_index.tolist() for v in voxels] == [[0, 0, 0], [2, 0, 0]]
    assert voxels[0].grid_index.dtype == np.int32
    assert np.allclose(voxels[0].color, [1, 0, 0]) and np.allclose(voxels[1].color, [0, 0.5, 0.5])
    assert vg.has_voxels() and vg.has_colors() and len(vg) == 2
    assert vg.get_voxel((1.05, 0.0, 0.0)).tolist() == [2, 0, 0]
    assert vg.check_if_included(np.array([[0.0, 0, 0], [0.5, 0, 0], [1.2, 0.1, 0]])) == [True, False, True]


def test_cloud_matches_open3d():
    vg = VG.create_from_point_cloud(make_cloud(), 0.5)
    voxels = vg.get_voxels()
    assert len(voxels) == 166
    assert np.allclose(vg.origin, [-3.218926805107407, -2.235063031791696, -1.2264119489149883], atol=1e-12)
    assert fp([v.grid_index for v in voxels]) == 582301.0
    assert fp([v.color for v in voxels]) == pytest.approx(61809.22903728997, rel=1e-12)
    assert vg.get_voxel((0.1, 0.2, 0.3)).tolist() == [6, 4, 3]
    queries = np.array([[0.0, 0.0, 0.0], [2.9, 1.9, 0.9], [10.0, 0.0, 0.0], [-2.0, 1.5, -0.5]])
    assert vg.check_if_included(o3d.utility.Vector3dVector(queries)) == [False, False, False, True]
    # every input point's cell is occupied (analytic)
    assert all(vg.check_if_included(make_inputs()[0]))


def test_within_bounds():
    # o3d drops the points outside the bounds (voxelgrid.h); Open3D keeps them, so the reference was
    # recorded on the points inside.
    cloud, colors = make_inputs()
    pcd = make_cloud()
    vg = VG.create_from_point_cloud_within_bounds(pcd, 0.5, (-1.0, -1.0, -1.0), (1.0, 1.0, 1.0))
    assert np.allclose(vg.origin, [-1, -1, -1])
    voxels = vg.get_voxels()
    assert len(voxels) == 32
    assert fp([v.grid_index for v in voxels]) == 8328.0
    assert fp([v.color for v in voxels]) == pytest.approx(2328.7454630027732, rel=1e-12)
    assert all(0 <= i < 4 for v in voxels for i in v.grid_index)


def test_from_mesh_box():
    vg = VG.create_from_triangle_mesh(o3d.geometry.TriangleMesh.create_box(), 0.3)
    voxels = vg.get_voxels()
    assert np.allclose(vg.origin, [-0.15, -0.15, -0.15])
    assert len(voxels) == 56  # Open3D 0.20: the surface shell of a 4 x 4 x 4 grid (64 - 2^3)
    assert fp([v.grid_index for v in voxels]) == 25368.0
    assert [1, 1, 1] not in [v.grid_index.tolist() for v in voxels]


def test_errors():
    pcd = make_cloud()
    for size in (0.0, -1.0, np.nan):
        with pytest.raises(ValueError):
            VG.create_from_point_cloud(pcd, size)
    with pytest.raises(ValueError):
        VG.create_from_point_cloud(o3d.geometry.PointCloud(), 0.5)
    with pytest.raises(ValueError):
        VG.create_from_point_cloud_within_bounds(pcd, 0.5, (1, 1, 1), (-1, -1, -1))
    with pytest.raises(ValueError):
        VG.create_from_triangle_mesh(o3d.geometry.TriangleMesh(), 0.5)
    vg = VG.create_from_point_cloud(pcd, 0.5)
    with pytest.raises(ValueError):
        vg.check_if_included(np.zeros((2, 2)))
    with pytest.raises(ValueError):
        vg.get_voxel((np.nan, 0, 0))
    assert VG().is_empty()  # Open3D's default constructor (filled by add_voxel / create_from_octree)
