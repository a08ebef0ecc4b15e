#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's TSDF integration of its rgbd_integration tutorial frames (open3d/RGBD, trajectory.log, voxel
4/512 m, sdf_trunc 0.04, RGB8), for tests/core/tsdf_test.cpp and the bindings' TSDF tests.

Open3D 0.20.0's ScalableTSDFVolume extracts nothing here; its UniformTSDFVolume (length 4, resolution 512, origin
(-3.5, -1.5, 0.5), the same voxel grid as a scalable volume's) is the reference.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_tsdf.py [DATA_ROOT]
"""
import os
import sys

import numpy as np
import open3d as o3d

root = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("O3D_TEST_DATA", os.path.join(os.path.dirname(__file__), "../../../shared/data"))
base = os.path.join(root, "open3d/RGBD/")
poses = []
lines = open(base + "trajectory.log").read().split("\n")
for i in range(0, len(lines) - 4, 5):
    if not lines[i].strip(): break
    poses.append(np.array([[float(x) for x in l.split()] for l in lines[i+1:i+5]]))
K = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
for kind in ["scalable", "uniform"]:
    if kind == "scalable":
        vol = o3d.pipelines.integration.ScalableTSDFVolume(voxel_length=4.0/512, sdf_trunc=0.04, color_type=o3d.pipelines.integration.TSDFVolumeColorType.RGB8)
    else:
        vol = o3d.pipelines.integration.UniformTSDFVolume(length=4.0, resolution=512, sdf_trunc=0.04, color_type=o3d.pipelines.integration.TSDFVolumeColorType.RGB8, origin=[-3.5,-1.5,0.5])
    for i in range(len(poses)):
        c = o3d.io.read_image(base + "color/%05d.jpg" % i)
        d = o3d.io.read_image(base + "depth/%05d.png" % i)
        rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(c, d, depth_trunc=4.0, convert_rgb_to_intensity=False)
        vol.integrate(rgbd, K, np.linalg.inv(poses[i]))
    m = vol.extract_triangle_mesh()
    p = vol.extract_point_cloud()
    v = np.asarray(m.vertices)
    print(kind, "vertices", len(v), "triangles", len(m.triangles), "points", len(p.points))
    if len(v):
        print(" vsum", v.sum(0).tolist(), "min", v.min(0).tolist(), "max", v.max(0).tolist(), "colmean", np.asarray(m.vertex_colors).mean(0).tolist())
