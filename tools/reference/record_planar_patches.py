#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D 0.20's detect_planar_patches results on the deterministic scenes of
tests/core/planar_patches_test.cpp (the test builds the same clouds with the same splitmix64 stream).

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_planar_patches.py
"""
import math

import numpy as np
import open3d as o3d

MASK = (1 << 64) - 1


class SplitMix64:
    """Same generator as the test's: uniform doubles in [0, 1) from the top 53 bits."""

    def __init__(self, seed):
        self.state = seed & MASK

    def uniform(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        z ^= z >> 31
        return (z >> 11) * (1.0 / 9007199254740992.0)

    def sym(self, a):
        return a * (2.0 * self.uniform() - 1.0)


def add_rectangle(rng, pts, nrm, c, u, v, hu, hv, n, count, noise, normal_noise=0.0):
    c, u, v, n = (np.asarray(x, dtype=float) for x in (c, u, v, n))
    for _ in range(count):
        a, b, e = rng.sym(hu), rng.sym(hv), rng.sym(noise)
        pts.append(c + a * u + b * v + e * n)
        m = n
        if normal_noise > 0:
            x, y, z = rng.sym(normal_noise), rng.sym(normal_noise), rng.sym(normal_noise)
            m = n + np.array([x, y, z])
            m = m / np.linalg.norm(m)
        nrm.append(m)


def rotation_zyx(ax, ay, az):
    cx, sx, cy, sy, cz, sz = math.cos(ax), math.sin(ax), math.cos(ay), math.sin(ay), math.cos(az), math.sin(az)
    rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return rz @ ry @ rx


BOX_HALF = [1.0, 0.75, 0.5]
BOX_SHIFT = np.array([0.3, -0.2, 0.1])


def box_scene():
    rng, pts, nrm = SplitMix64(11), [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            a1, a2 = (axis + 1) % 3, (axis + 2) % 3
            n = sign * np.eye(3)[axis]
            count = int(1500.0 * BOX_HALF[a1] * BOX_HALF[a2])
            add_rectangle(rng, pts, nrm, BOX_HALF[axis] * n, np.eye(3)[a1], np.eye(3)[a2], BOX_HALF[a1],
                          BOX_HALF[a2], n, count, 0.004)
    r = rotation_zyx(0.3, -0.2, 0.5)
    return np.array(pts) @ r.T + BOX_SHIFT, np.array(nrm) @ r.T


def planes_and_sphere_scene():
    rng, pts, nrm = SplitMix64(22), [], []
    add_rectangle(rng, pts, nrm, [0, 0, 0], [1, 0, 0], [0, 1, 0], 1.0, 1.0, [0, 0, 1], 3000, 0.003)
    add_rectangle(rng, pts, nrm, [-1, 0, 0.75], [0, 1, 0], [0, 0, 1], 1.0, 0.75, [1, 0, 0], 2250, 0.003)
    for _ in range(2500):
        z = 2.0 * rng.uniform() - 1.0
        phi = 2.0 * math.pi * rng.uniform()
        s = math.sqrt(max(0.0, 1.0 - z * z))
        d = np.array([s * math.cos(phi), s * math.sin(phi), z])
        nrm.append(d)
        pts.append(np.array([0.3, 0.2, 0.6]) + 0.35 * d)
    return np.array(pts), np.array(nrm)


def noisy_plane_scene():
    rng, pts, nrm = SplitMix64(33), [], []
    n = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
    u = np.cross(n, [0, 0, 1.0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    add_rectangle(rng, pts, nrm, [0.5, -1.0, 2.0], u, v, 1.0, 0.6, n, 3000, 0.01, 0.05)
    return np.array(pts), np.array(nrm)


def report(name, pts, nrm, **kwargs):
    pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(pts))
    pc.normals = o3d.utility.Vector3dVector(nrm)
    boxes = pc.detect_planar_patches(**kwargs)
    print(f"{name} {kwargs}: {len(pts)} points, {len(boxes)} patches")
    for b in boxes:
        print(f"  normal {np.round(b.R[:, 2], 4)} centre {np.round(b.center, 4)} extent {np.round(b.extent, 4)}")


def main():
    np.set_printoptions(suppress=True)
    report("box", *box_scene())
    for edge in (1.6, 1.9, 2.1):
        report("box", *box_scene(), min_plane_edge_length=edge)
    report("planes and sphere", *planes_and_sphere_scene())
    report("noisy plane", *noisy_plane_scene())


if __name__ == "__main__":
    main()
