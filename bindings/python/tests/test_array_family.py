"""The generic array paths every geometry shares (o3d_<noun>_*_array through _has_array, _set_array,
_array_copy, _readonly_view), on the geometries whose public Open3D API does not reach all of them."""
import numpy as np
import pytest

import o3d

FEATURE_DATA = 0  # O3D_FEATURE_DATA
POINTS = 0        # O3D_POINTCLOUD_POINTS


def test_feature_set_array_takes_descriptor_rows_in_float32_and_float64():
    f = o3d.pipelines.registration.Feature()
    f.resize(4, 0)
    assert not f._has_array(FEATURE_DATA)
    rows = np.arange(12, dtype=np.float32).reshape(3, 4)  # 3 descriptors of dimension 4, one per row
    f._set_array(FEATURE_DATA, rows)
    assert f._has_array(FEATURE_DATA) and f.dimension() == 4 and f.num() == 3
    np.testing.assert_array_equal(f.data, rows.T)  # Open3D's (dimension, num) view
    np.testing.assert_array_equal(f._array_copy(FEATURE_DATA), rows)
    view = f._readonly_view(FEATURE_DATA)
    assert not view.flags.writeable
    f._set_array(FEATURE_DATA, rows.astype(np.float64) * 2)
    np.testing.assert_array_equal(f.data[:, 2], [16, 18, 20, 22])
    with pytest.raises(ValueError):
        f._set_array(FEATURE_DATA, np.zeros((2, 3)))  # rows of the wrong dimension
    with pytest.raises(ValueError):
        f._has_array(7)  # no such array


def test_point_cloud_generic_paths_match_the_named_properties():
    pcd = o3d.geometry.PointCloud()
    pcd._set_array(POINTS, np.eye(3, dtype=np.float32))
    assert pcd._has_array(POINTS) and pcd.has_points()
    np.testing.assert_array_equal(np.asarray(pcd.points), np.eye(3))


def test_image_bytes_replace_in_place_and_empty_images():
    img = o3d.geometry.Image(np.zeros((2, 3), dtype=np.uint8))
    assert not img.is_empty()
    img._set_data(bytes(range(6)))
    np.testing.assert_array_equal(np.asarray(img), np.arange(6, dtype=np.uint8).reshape(2, 3))
    assert img._data_copy() == bytes(range(6))
    with pytest.raises(ValueError):
        img._set_data(bytes(5))  # the shape stays: exactly 6 bytes
    assert o3d.geometry.Image().is_empty()


def test_voxel_grid_has_voxels_and_arrays():
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.array([[0, 0, 0], [1, 1, 1.0]])))
    grid = o3d.geometry.VoxelGrid.create_from_point_cloud(pcd, voxel_size=0.5)
    assert grid.has_voxels() and len(grid.get_voxels()) == 2
