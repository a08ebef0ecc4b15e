"""Inputs shared by the round-2 geometry tests, synthesized exactly as tools/reference/record_python_round2.py
does (the Open3D 0.20 reference numbers in the tests were recorded on these)."""
import numpy as np

import o3d


def make_inputs():
    rng = np.random.default_rng(7)
    cloud = rng.uniform(-1.0, 1.0, size=(200, 3)) * np.array([3.0, 2.0, 1.0])
    colors = rng.uniform(0.0, 1.0, size=(200, 3))
    return cloud, colors


def make_cloud():
    cloud, colors = make_inputs()
    pcd = o3d.geometry.PointCloud(cloud)
    pcd.colors = colors
    return pcd


def fp(a):
    """sum_i (i + 1) * a_i over the flattened array (order and values must both match)."""
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def rot_xyz(a, b, c):
    """Open3D's get_rotation_matrix_from_xyz: Rx(a) @ Ry(b) @ Rz(c)."""
    ca, sa, cb, sb, cc, sc = np.cos(a), np.sin(a), np.cos(b), np.sin(b), np.cos(c), np.sin(c)
    rx = np.array([[1, 0, 0], [0, ca, -sa], [0, sa, ca]])
    ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    rz = np.array([[cc, -sc, 0], [sc, cc, 0], [0, 0, 1]])
    return rx @ ry @ rz


def cube_corners(lo=(0.0, 0.0, 0.0), hi=(1.0, 1.0, 1.0)):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
