#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Record Open3D's point-cloud smoothing filters (PointCloud.smooth_mls / smooth_laplacian / smooth_taubin /
smooth_bilateral) for tests/core/point_cloud_smoothing_test.cpp.

Run with the open3d 0.20.0 wheel:  python tools/reference/record_point_cloud_smoothing.py
The clouds come from splitmix64 (bit for bit the generator in the C++ test). Prints, per case, the mean and
max displacement, the mean output point and a few output points (and normals) as C++ initialisers.
"""
import numpy as np
import open3d as o3d

o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
print("open3d", o3d.__version__)
M = 2**64


class SplitMix64:
    def __init__(self, seed):
        self.state = seed % M

    def uniform(self):  # [0, 1), 53 bits
        self.state = (self.state + 0x9E3779B97F4A7C15) % M
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) % M
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) % M
        z ^= z >> 31
        return (z >> 11) * 2.0**-53


def noisy_plane(n, seed):
    # z = 0.1 x + 0.05 y + uniform noise of amplitude 0.01, (x, y) uniform in [-1, 1]^2.
    g = SplitMix64(seed)
    pts = []
    for _ in range(n):
        x = -1.0 + 2.0 * g.uniform()
        y = -1.0 + 2.0 * g.uniform()
        z = 0.1 * x + 0.05 * y + 0.02 * (g.uniform() - 0.5)
        pts.append((x, y, z))
    return np.array(pts)


def noisy_sphere(n, seed):
    # Directions from the cube [-1, 1]^3 (|d| >= 0.1), radius 1 + uniform noise of amplitude 0.02.
    g = SplitMix64(seed)
    pts, normals = [], []
    while len(pts) < n:
        x = -1.0 + 2.0 * g.uniform()
        y = -1.0 + 2.0 * g.uniform()
        z = -1.0 + 2.0 * g.uniform()
        r = 1.0 + 0.04 * (g.uniform() - 0.5)
        length = np.sqrt(x * x + y * y + z * z)
        if length < 0.1:
            continue
        pts.append((x / length * r, y / length * r, z / length * r))
        normals.append((x / length, y / length, z / length))
    return np.array(pts), np.array(normals)


def cloud(points, normals=None):
    c = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    if normals is not None:
        c.normals = o3d.utility.Vector3dVector(normals)
    return c


def vec(v):
    return "{%.17g, %.17g, %.17g}" % tuple(v)


SHOW = (0, 137, 299)


def report(name, before, after, normals=False):
    a, b = np.asarray(before.points), np.asarray(after.points)
    disp = np.linalg.norm(b - a, axis=1)
    print(f"// {name}")
    print(f"//   mean displacement {disp.mean():.17g}, max {disp.max():.17g}, mean point {vec(b.mean(0))}")
    for i in SHOW:
        print(f"//   point {i}: {vec(b[i])}")
    if normals:
        n = np.asarray(after.normals)
        for i in SHOW:
            print(f"//   normal {i}: {vec(n[i])}")


K = o3d.geometry.KDTreeSearchParamKNN
R = o3d.geometry.KDTreeSearchParamRadius
H = o3d.geometry.KDTreeSearchParamHybrid

plane = cloud(noisy_plane(300, 7))
sphere_points, sphere_normals = noisy_sphere(400, 11)
sphere = cloud(sphere_points)
sphere_n = cloud(sphere_points, sphere_normals)

report("mls plane Hybrid(0.3, 30)", plane, plane.smooth_mls(H(0.3, 30)))
report("mls plane Knn(20)", plane, plane.smooth_mls(K(20)))
report("mls sphere Radius(0.25)", sphere, sphere.smooth_mls(R(0.25)))
report("mls sphere with normals Hybrid(0.3, 30)", sphere_n, sphere_n.smooth_mls(H(0.3, 30)), normals=True)
report("laplacian sphere (10, 0.5, 20, False)", sphere, sphere.smooth_laplacian(10, 0.5, 20, False))
report("laplacian sphere (10, 0.5, 20, True)", sphere, sphere.smooth_laplacian(10, 0.5, 20, True))
report("taubin sphere (10, 0.5, -0.53, 20, False)", sphere, sphere.smooth_taubin(10, 0.5, -0.53, 20, False))
report("taubin sphere (10, 0.5, -0.53, 20, True)", sphere, sphere.smooth_taubin(10, 0.5, -0.53, 20, True))
report("bilateral sphere with normals Hybrid(0.3, 30), 0.1, 0.02", sphere_n,
       sphere_n.smooth_bilateral(H(0.3, 30), 0.1, 0.02))
report("bilateral plane without normals Knn(15), 0.2, 0.01", plane, plane.smooth_bilateral(K(15), 0.2, 0.01),
       normals=True)
