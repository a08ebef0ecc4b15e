import numpy as np
import pytest

import o3d


def test_vector3dvector_keeps_float64_and_float32():
    a64 = np.arange(12, dtype=np.float64).reshape(4, 3)
    a32 = a64.astype(np.float32)
    assert np.asarray(o3d.utility.Vector3dVector(a64)).dtype == np.float64
    assert np.asarray(o3d.utility.Vector3dVector(a32)).dtype == np.float32
    np.testing.assert_array_equal(np.asarray(o3d.utility.Vector3dVector(a32)), a32)


def test_vector3dvector_copies_input_and_asarray_is_a_view():
    a = np.ones((2, 3))
    v = o3d.utility.Vector3dVector(a)
    a[0, 0] = 5.0
    assert np.asarray(v)[0, 0] == 1.0  # copied at construction, as Open3D
    view = np.asarray(v)
    view[1, 1] = 7.0
    assert v[1][1] == 7.0


def test_vector3dvector_list_ops():
    v = o3d.utility.Vector3dVector()
    assert len(v) == 0
    v.append([1, 2, 3])
    v.extend([[4, 5, 6], [7, 8, 9]])
    assert len(v) == 3
    np.testing.assert_array_equal(v[2], [7, 8, 9])
    assert list(v.pop(0)) == [1, 2, 3]
    assert len(v) == 2


def test_vector3dvector_wrong_shape():
    with pytest.raises(ValueError):
        o3d.utility.Vector3dVector(np.zeros((4, 2)))
    with pytest.raises(ValueError):
        o3d.utility.Vector3dVector(np.array(["a", "b", "c"]))


def test_int_and_double_vectors():
    iv = o3d.utility.IntVector([3, 1, 2])
    assert np.asarray(iv).dtype == np.int32
    assert list(iv) == [3, 1, 2]
    dv = o3d.utility.DoubleVector([0.5, 1.5])
    assert np.asarray(dv).dtype == np.float64
    assert float(np.asarray(dv).sum()) == 2.0
    tri = o3d.utility.Vector3iVector([[0, 1, 2]])
    assert np.asarray(tri).dtype == np.int32 and np.asarray(tri).shape == (1, 3)
