"""o3d.geometry.Octree: convert_from_point_cloud, root geometry, locate_leaf_node.

Reference numbers: tools/reference/record_python_round2.py (Open3D 0.20.0), on round2_data.make_inputs().
"""
import numpy as np
import pytest

import o3d
from round2_data import make_cloud, make_inputs


def test_root_matches_open3d():
    oc = o3d.geometry.Octree(3)
    assert oc.max_depth == 3 and oc.is_empty()
    oc.convert_from_point_cloud(make_cloud(), size_expand=0.01)
    assert np.allclose(oc.origin, [-2.968926805107407, -2.9806288548263717, -2.9768967847020393], atol=1e-12)
    assert oc.size == pytest.approx(6.022912131366165, rel=1e-12)
    assert not oc.is_empty() and 0 < oc._num_leaf_nodes() <= 200


def test_locate_leaf_matches_open3d():
    cloud, colors = make_inputs()
    oc = o3d.geometry.Octree(max_depth=3)
    oc.convert_from_point_cloud(make_cloud())
    leaf, info = oc.locate_leaf_node(np.array([0.1, 0.2, 0.3]))
    assert isinstance(leaf, o3d.geometry.OctreePointColorLeafNode) and isinstance(info, o3d.geometry.OctreeNodeInfo)
    assert sorted(leaf.indices) == [20, 74, 121, 158, 196]  # Open3D 0.20
    # the mean color of the leaf's points (octree.h); Open3D 0.20 keeps the last inserted point's color
    # ([0.4919280004203891, 0.9894827748174284, 0.08689784211301277] = colors[196])
    assert np.allclose(leaf.color, colors[[20, 74, 121, 158, 196]].mean(axis=0))
    assert np.allclose(info.origin, [0.0425292605756753, 0.030827210856710696, 0.034559280981043106])
    assert info.size == pytest.approx(0.7528640164207706) and info.depth == 3 and info.child_index == 0
    leaf, info = oc.locate_leaf_node(cloud[5])
    assert sorted(leaf.indices) == [0, 5, 46, 197]
    assert np.allclose(info.origin, [0.0425292605756753, 1.536555243698252, 0.034559280981043106])
    # every point of a leaf lies in the leaf's cube (analytic)
    p = cloud[leaf.indices]
    assert np.all(p >= info.origin - 1e-12) and np.all(p <= info.origin + info.size + 1e-12)
    assert oc.locate_leaf_node((2.5, -1.5, 0.8)) == (None, None)  # an empty cell
    assert oc.locate_leaf_node((100.0, 0.0, 0.0)) == (None, None)  # outside the root


def test_every_point_in_its_leaf():
    cloud, _ = make_inputs()
    oc = o3d.geometry.Octree(4)
    oc.convert_from_point_cloud(make_cloud(), 0.01)
    for i in range(0, 200, 17):
        leaf, info = oc.locate_leaf_node(cloud[i])
        assert i in leaf.indices and info.depth == 4
        assert info.size == pytest.approx(oc.size / 16)


def test_errors():
    with pytest.raises(ValueError):
        o3d.geometry.Octree(0)
    oc = o3d.geometry.Octree(2)
    with pytest.raises(ValueError):
        oc.convert_from_point_cloud(o3d.geometry.PointCloud())
    with pytest.raises(ValueError):
        oc.convert_from_point_cloud(make_cloud(), size_expand=-1.0)
    with pytest.raises(ValueError):
        oc.locate_leaf_node((0.0, 0.0))
