"""VoxelGrid editing, dense grids, cell geometry, carving and the Octree <-> VoxelGrid conversions, insert_point.

Answers are analytic; the carving counts were also checked against the Open3D 0.20 wheel (same counts and grid-index
sums on the same scenes). Where o3d differs from Open3D 0.20 on purpose it is said so below.
"""
import numpy as np
import pytest

import o3d

G = o3d.geometry
VG = G.VoxelGrid


def indices(vg):
    return {tuple(int(i) for i in v.grid_index) for v in vg.get_voxels()}


def camera(tx=0.0):
    """64 x 64 pinhole, f = 50, centred, looking down +z from (-tx, 0, 0)."""
    cam = o3d.camera.PinholeCameraParameters()
    cam.intrinsic = o3d.camera.PinholeCameraIntrinsic(64, 64, 50.0, 50.0, 31.5, 31.5)
    e = np.eye(4)
    e[0, 3] = tx
    cam.extrinsic = e
    return cam


def cube():
    """4 x 4 x 4 voxels of 0.5 filling [-1, 1] x [-1, 1] x [2, 4]."""
    return VG.create_dense((-1, -1, 2), (0.2, 0.4, 0.6), 0.5, 2, 2, 2)


def test_dense_counts_centres_and_corners():
    vg = VG.create_dense(origin=(1.0, 2.0, 3.0), color=(0.1, 0.2, 0.3), voxel_size=0.5, width=1.0, height=1.5,
                         depth=1.2)  # round(2.4) = 2 along z
    assert len(vg) == 2 * 3 * 2 and vg.voxel_size == 0.5 and np.allclose(vg.origin, (1, 2, 3))
    assert indices(vg) == {(i, j, k) for i in range(2) for j in range(3) for k in range(2)}
    assert all(np.allclose(v.color, (0.1, 0.2, 0.3)) for v in vg.get_voxels())
    c = vg.get_voxel_center_coordinate((1, 2, 0))
    assert c.shape == (3,) and np.allclose(c, (1 + 0.75, 2 + 1.25, 3 + 0.25))
    assert np.allclose(vg.get_voxel_center_coordinate(np.array([-1, 0, 7])), (0.75, 2.25, 6.75))  # unoccupied cell
    pts = vg.get_voxel_bounding_points(idx := np.array([1, 2, 0], np.int32))
    assert isinstance(pts, o3d.utility.Vector3dVector)
    p = np.asarray(pts)
    assert p.shape == (8, 3)
    centre = vg.get_voxel_center_coordinate(idx)
    assert np.allclose(np.abs(p - centre), 0.25)  # every corner at centre +- half a voxel
    assert len({tuple(r) for r in np.round(p, 12)}) == 8
    # Open3D 0.20's order (recorded with the wheel on a 0.5 grid at the origin, cell (1, 0, 0))
    g = VG.create_dense((0, 0, 0), (1, 0, 0), 0.5, 1, 1, 1)
    assert np.allclose(np.asarray(g.get_voxel_bounding_points([1, 0, 0])),
                       [[0.5, 0, 0], [0.5, 0, 0.5], [1, 0, 0], [1, 0, 0.5],
                        [0.5, 0.5, 0], [0.5, 0.5, 0.5], [1, 0.5, 0], [1, 0.5, 0.5]])


def test_add_replaces_and_remove_drops():
    vg = VG.create_dense((0, 0, 0), (1, 0, 0), 1.0, 2, 1, 1)
    assert indices(vg) == {(0, 0, 0), (1, 0, 0)}
    assert vg.add_voxel(G.Voxel([1, 0, 0], [0, 1, 0])) is None
    vg.add_voxel(G.Voxel(np.array([5, -2, 3]), (0, 0, 1)))
    colors = {tuple(v.grid_index): v.color for v in vg.get_voxels()}
    assert len(colors) == 3 and np.allclose(colors[(1, 0, 0)], (0, 1, 0)) and np.allclose(colors[(0, 0, 0)], (1, 0, 0))
    assert np.allclose(colors[(5, -2, 3)], (0, 0, 1))
    assert vg.check_if_included([[5.5, -1.5, 3.5]]) == [True]
    vg.remove_voxel([0, 0, 0])
    assert indices(vg) == {(1, 0, 0), (5, -2, 3)}
    vg.remove_voxel((7, 7, 7))  # none there: nothing happens
    assert len(vg) == 2
    v = G.Voxel([1, 2, 3])
    assert v.grid_index.dtype == np.int32 and np.allclose(G.Voxel(v).color, 0)
    e = G.VoxelGrid()
    assert e.is_empty()
    e.add_voxel(G.Voxel((0, 0, 0), (0.5, 0.5, 0.5)))
    assert len(e) == 1


def test_edit_errors():
    vg = VG.create_dense((0, 0, 0), (1, 0, 0), 1.0, 1, 1, 1)
    with pytest.raises(TypeError):
        vg.add_voxel((0, 0, 0))
    with pytest.raises(ValueError):
        vg.add_voxel(G.Voxel((0, 0, 0), (np.nan, 0, 0)))
    with pytest.raises(ValueError):
        vg.remove_voxel((0, 0))
    with pytest.raises(ValueError):
        vg.get_voxel_center_coordinate((0.5, 0, 0))  # not integers
    with pytest.raises(ValueError):
        VG.create_dense((0, 0, 0), (1, 0, 0), 0.0, 1, 1, 1)  # voxel size 0
    with pytest.raises(ValueError):
        VG.create_dense((0, 0, 0), (1, 0, 0), 1.0, -1, 1, 1)
    with pytest.raises(ValueError):
        VG.create_from_triangle_mesh_within_bounds(G.TriangleMesh.create_box(), 0.0, (0, 0, 0), (1, 1, 1))
    assert len(vg) == 1


def test_mesh_within_bounds():
    box = G.TriangleMesh.create_box(1, 1, 1)
    whole = VG.create_from_triangle_mesh_within_bounds(box, 0.25, (0, 0, 0), (1, 1, 1))
    # cells 0..4 per axis touch the box; the surface: two full 5 x 5 faces and three 16-cell rings between
    assert len(whole) == 25 + 3 * 16 + 25 and np.allclose(whole.origin, 0) and whole.voxel_size == 0.25
    half = VG.create_from_triangle_mesh_within_bounds(input=box, voxel_size=0.25, min_bound=(0, 0, 0),
                                                      max_bound=(0.5, 1, 1))
    # only the cells of the bounds (i <= 2) are made (Open3D 0.20 makes all 98, ignoring max_bound)
    assert len(half) == 25 + 2 * 16 and indices(half) == {t for t in indices(whole) if t[0] <= 2}


def test_silhouette_all_ones_keeps_all_zeros_removes_all():
    vg = cube()
    assert vg.carve_silhouette(G.Image(np.ones((64, 64), np.float32)), camera()) is vg
    assert len(vg) == 64
    vg.carve_silhouette(G.Image(np.zeros((64, 64), np.float32)), camera(), keep_voxels_outside_image=True)
    assert len(vg) == 0


def test_depth_map_carve():
    # A wall at depth 3: voxels in front of it (z in [2, 2.5]) have no corner on or behind it and go
    vg = cube()
    out = vg.carve_depth_map(G.Image(np.full((64, 64), 3.0, np.float32)), camera())
    assert out is vg and len(vg) == 48 and {k for _, _, k in indices(vg)} == {1, 2, 3}
    # Near (2.2) on the left half of the image (u < 32: x < 0, i = 0, 1), far (3.6) on the right: the left columns
    # keep all 4 layers; column 3 only the layer reaching 3.6 (k = 3); column 2's corners at x = 0 project to
    # u = 31.5, between the halves, where the depth reads 2.9 (interpolated): it keeps the layers reaching 2.9
    vg = cube()
    a = np.full((64, 64), 3.6, np.float32)
    a[:, :32] = 2.2
    vg.carve_depth_map(depth_map=G.Image(a), camera_params=camera(), keep_voxels_outside_image=False)
    got = indices(vg)
    assert {t for t in got if t[0] <= 1} == {(i, j, k) for i in range(2) for j in range(4) for k in range(4)}
    assert {t for t in got if t[0] == 2} == {(2, j, k) for j in range(4) for k in (1, 2, 3)}
    assert {t for t in got if t[0] == 3} == {(3, j, 3) for j in range(4)}
    assert len(got) == 48 and sum(map(sum, got)) == 208  # Open3D 0.20: 48 voxels, grid-index sum 208


@pytest.mark.parametrize("carve", ["carve_depth_map", "carve_silhouette"])
def test_keep_voxels_outside_image(carve):
    # seen from x = -3 the grid spans x in [2, 4] in camera space; a corner is in the image when
    # u = 50 x / z + 31.5 < 64, i.e. x < 0.65 z: only i = 0 with k >= 2 (x = 2, z up to 3.5 or 4) and i = 1 with
    # k = 3 (x = 2.5, z = 4) have one; the depth map (3.0) is behind none of them
    img = G.Image(np.full((64, 64), 3.0 if carve == "carve_depth_map" else 1.0, np.float32))
    vg = cube()
    getattr(vg, carve)(img, camera(3.0))
    got = indices(vg)
    assert len(got) == 12 and sum(map(sum, got)) == 54  # Open3D 0.20: 12 voxels, grid-index sum 54
    assert got == {(0, j, k) for j in range(4) for k in (2, 3)} | {(1, j, 3) for j in range(4)}
    vg = cube()
    getattr(vg, carve)(img, camera(3.0), keep_voxels_outside_image=True)
    assert len(vg) == 64


def test_carve_errors():
    vg = cube()
    ones = G.Image(np.ones((64, 64), np.float32))
    cam = camera()
    e = np.eye(4)
    e[0, 0] = 2.0  # a scale: not rigid
    cam.extrinsic = e
    with pytest.raises(ValueError):
        vg.carve_silhouette(ones, cam)
    with pytest.raises(ValueError):
        vg.carve_silhouette(G.Image(np.ones((64, 64), np.uint8)), camera())  # uint8 mask
    with pytest.raises(ValueError):
        vg.carve_depth_map(G.Image(np.ones((32, 64), np.float32)), camera())  # not the intrinsic's size
    with pytest.raises(TypeError):
        vg.carve_depth_map(ones, np.eye(4))
    assert len(vg) == 64


def insert_all(oc, pts):
    leaf = G.OctreePointColorLeafNode
    for i, p in enumerate(pts):
        assert oc.insert_point(np.array(p, float), leaf.get_init_function(),
                               leaf.get_update_function(i, (i / 10, 0, 0))) is None


PTS = [(0.5, 0.5, 0.5), (0.6, 0.4, 0.5), (3.5, 3.5, 3.5), (1.5, 0.2, 0.2), (9, 9, 9)]


def test_octree_insert_point():
    oc = G.Octree(2, (0, 0, 0), 4.0)
    assert oc.max_depth == 2 and oc.size == 4.0 and np.allclose(oc.origin, 0) and oc.is_empty()
    insert_all(oc, PTS)  # the last point is outside the root: ignored
    assert oc._num_leaf_nodes() == 3
    leaf, info = oc.locate_leaf_node((0.5, 0.5, 0.5))
    # the mean color of the leaf's points (Open3D 0.20 keeps the last point's, 0.1)
    assert leaf.indices == [0, 1] and np.allclose(leaf.color, (0.05, 0, 0))
    assert np.allclose(info.origin, 0) and info.size == 1.0 and info.depth == 2
    # o3d's own form answers whether the point was inside the root; the Open3D internal-node functions are accepted
    assert oc.insert_point((3.9, 0.1, 0.1), 7, (1, 1, 1)) is True
    assert oc.insert_point((-0.1, 0, 0), 8, (1, 1, 1)) is False
    oc.insert_point((3.9, 0.2, 0.2), G.OctreePointColorLeafNode.get_init_function(),
                    G.OctreePointColorLeafNode.get_update_function(9, (0, 1, 1)),
                    G.OctreeInternalPointNode.get_init_function(), G.OctreeInternalPointNode.get_update_function(9))
    leaf, _ = oc.locate_leaf_node((3.9, 0.1, 0.1))
    assert leaf.indices == [7, 9] and np.allclose(leaf.color, (0.5, 1, 1)) and oc._num_leaf_nodes() == 4
    # the leaf functions also work on a node, as Open3D's
    node = G.OctreePointColorLeafNode.get_init_function()()
    G.OctreePointColorLeafNode.get_update_function(3, (1, 0, 0))(node)
    assert node.indices == [3] and np.allclose(node.color, (1, 0, 0))


def test_octree_bounds_and_errors():
    assert G.Octree.is_point_in_bound((0, 0.5, 0.99), (0, 0, 0), 1.0)
    assert not G.Octree.is_point_in_bound(point=(1, 0.5, 0.5), origin=(0, 0, 0), size=1.0)  # half-open
    assert not G.Octree.is_point_in_bound((-1e-9, 0, 0), (0, 0, 0), 1.0)
    with pytest.raises(ValueError):
        G.Octree(2, (0, 0, 0), 0.0)
    with pytest.raises(ValueError):
        G.Octree(0, (0, 0, 0), 1.0)
    oc = G.Octree(max_depth=2, origin=(0, 0, 0), size=1.0)
    with pytest.raises(ValueError):
        oc.insert_point((0.5, 0.5, 0.5), -1, (0, 0, 0))  # negative index
    with pytest.raises(ValueError):
        oc.insert_point((np.nan, 0.5, 0.5), 1, (0, 0, 0))
    with pytest.raises(NotImplementedError):
        oc.insert_point((0.5, 0.5, 0.5), lambda: None, lambda node: None)  # only point-colour leaves
    assert oc.is_empty()


def test_octree_to_voxel_grid_and_back():
    oc = G.Octree(2, (0, 0, 0), 4.0)
    insert_all(oc, PTS)
    vg = oc.to_voxel_grid()
    # voxel size 4 / 2^2, one voxel per leaf (Open3D 0.20 answers voxel_size 0 here)
    assert vg.voxel_size == 1.0 and np.allclose(vg.origin, 0)
    assert indices(vg) == {(0, 0, 0), (1, 0, 0), (3, 3, 3)}
    colors = {tuple(v.grid_index): v.color for v in vg.get_voxels()}
    assert np.allclose(colors[(0, 0, 0)], (0.05, 0, 0)) and np.allclose(colors[(1, 0, 0)], (0.3, 0, 0))
    # both forms of create_from_octree: on the class a new grid, on a grid (Open3D's) in place, answering None
    assert indices(VG.create_from_octree(oc)) == indices(vg)
    filled = G.VoxelGrid()
    assert filled.create_from_octree(oc) is None and indices(filled) == indices(vg) and filled.voxel_size == 1.0
    back = G.Octree(2)
    assert back.create_from_voxel_grid(voxel_grid=vg) is None
    assert np.allclose(back.origin, 0) and back.size == 4.0 and back._num_leaf_nodes() == 3
    # each leaf: the voxel's color and its position in the grid's (sorted) voxel order
    for position, (p, color) in enumerate([((0.5, 0.5, 0.5), 0.05), ((1.5, 0.5, 0.5), 0.3), ((3.5, 3.5, 3.5), 0.2)]):
        leaf, info = back.locate_leaf_node(p)
        assert leaf.indices == [position] and np.allclose(leaf.color, (color, 0, 0)) and info.size == 1.0
    assert indices(back.to_voxel_grid()) == indices(vg)
