#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's camera, RGB-D and back-projection numbers on the shared data, for
tests/core/camera_test.cpp, tests/core/rgbd_test.cpp, tests/core/depth_projection_test.cpp and the C tests.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_rgbd.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.
"""
import os
import re
import sys

import numpy as np
import open3d as o3d

# Pixels (u = column, v = row) sampled in every image; the tests repeat them.
PIXELS = [(320, 240), (100, 50), (600, 400), (10, 470), (400, 100), (213, 377)]
# Indices into the back-projected clouds; the tests repeat them.
POINT_INDICES = [0, 1000, 50000, 123456]


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def vec(v):
    return "{" + ", ".join(repr(float(x)) for x in v) + "}"


def mat(m):
    return "{" + ", ".join(vec(row) for row in np.asarray(m)) + "}"


def read_nyu_pgm(filename, byteorder=">"):
    """Open3D's RGB-D tutorial reader (rgbd_nyu.py): the PGM samples as big-endian 16-bit values."""
    with open(filename, "rb") as f:
        buffer = f.read()
    header, width, height, maxval = re.search(
        rb"(^P5\s(?:\s*#.*[\r\n])*(\d+)\s(?:\s*#.*[\r\n])*(\d+)\s(?:\s*#.*[\r\n])*(\d+)\s(?:\s*#.*[\r\n]\s)*)",
        buffer).groups()
    img = np.frombuffer(buffer, dtype=byteorder + "u2", count=int(width) * int(height),
                        offset=len(header)).reshape((int(height), int(width)))
    return img.astype("u2")


def read_ppm(filename):
    """Binary P6 with maxval 255, as the tutorial's matplotlib imread returns it (H x W x 3 uint8)."""
    with open(filename, "rb") as f:
        buffer = f.read()
    header, width, height = re.search(rb"(^P6\s+(\d+)\s+(\d+)\s+255\s)", buffer).groups()
    return np.frombuffer(buffer, dtype=np.uint8, count=int(width) * int(height) * 3,
                         offset=len(header)).reshape((int(height), int(width), 3)).copy()


def camera(root):
    print("// ---- camera")
    t = o3d.io.read_pinhole_camera_trajectory(os.path.join(root, "open3d", "RGBD", "trajectory.log"))
    print(f"// trajectory.log: {len(t.parameters)} poses")
    print(f"trajectory_log_extrinsic[0] = {mat(t.parameters[0].extrinsic)}")
    print(f"trajectory_log_extrinsic[4] = {mat(t.parameters[4].extrinsic)}")
    t = o3d.io.read_pinhole_camera_trajectory(os.path.join(root, "open3d", "RGBD", "odometry.log"))
    print(f"odometry_log_extrinsic[1] = {mat(t.parameters[1].extrinsic)}")
    print(f"odometry_log_extrinsic[4] = {mat(t.parameters[4].extrinsic)}")
    t = o3d.io.read_pinhole_camera_trajectory(os.path.join(root, "open3d", "camera_trajectory.json"))
    print(f"// camera_trajectory.json: {len(t.parameters)} poses")
    print(f"camera_trajectory_extrinsic[1] = {mat(t.parameters[1].extrinsic)}")
    print(f"camera_trajectory_extrinsic[30] = {mat(t.parameters[30].extrinsic)}")


def sample(name, rgbd):
    depth = np.asarray(rgbd.depth)
    color = np.asarray(rgbd.color)
    print(f"// {name}: color {color.shape} {color.dtype}, depth {depth.shape} {depth.dtype}")
    print(f"{name}_depth = {vec(depth[v, u] for u, v in PIXELS)}")
    if color.ndim == 2:
        print(f"{name}_intensity = {vec(color[v, u] for u, v in PIXELS)}")
    print(f"{name}_depth_sum = {float(depth.astype(np.float64).sum())!r}  // nonzero: {int((depth > 0).sum())}")


def datasets(root):
    print("// ---- dataset readers (pixels " + ", ".join(f"({u},{v})" for u, v in PIXELS) + ")")
    other = os.path.join(root, "open3d", "RGBD", "other_formats")
    R = o3d.geometry.RGBDImage
    color = o3d.io.read_image(os.path.join(other, "TUM_color.png"))
    depth = o3d.io.read_image(os.path.join(other, "TUM_depth.png"))
    sample("tum", R.create_from_tum_format(color, depth))
    color = o3d.io.read_image(os.path.join(other, "SUN_color.jpg"))
    depth = o3d.io.read_image(os.path.join(other, "SUN_depth.png"))
    sample("sun", R.create_from_sun_format(color, depth))
    color = o3d.geometry.Image(read_ppm(os.path.join(other, "NYU_color.ppm")))
    depth = o3d.geometry.Image(read_nyu_pgm(os.path.join(other, "NYU_depth.pgm")))
    sample("nyu", R.create_from_nyu_format(color, depth))
    rgbd_dir = os.path.join(root, "open3d", "RGBD")
    color = o3d.io.read_image(os.path.join(rgbd_dir, "color", "00000.jpg"))
    depth = o3d.io.read_image(os.path.join(rgbd_dir, "depth", "00000.png"))
    sample("redwood", R.create_from_redwood_format(color, depth))
    sample("default", R.create_from_color_and_depth(color, depth))


# Raw uint16 depth samples pushed through the SUN and NYU readers (a 1 x N synthetic image).
RAW_SAMPLES = [0, 1, 8, 1000, 8000, 55992, 56000, 0x0400, 0x0401, 0x4400, 0x1204, 0x1904, 0x1a04, 0x0444,
               0x8000, 0xff03, 0xffff]


def raw_mappings():
    print("// ---- SUN / NYU on raw samples " + ", ".join(hex(v) for v in RAW_SAMPLES))
    raw = np.array([RAW_SAMPLES], dtype=np.uint16)
    color = o3d.geometry.Image(np.zeros((1, len(RAW_SAMPLES), 3), np.uint8))
    R = o3d.geometry.RGBDImage
    for name, f in (("sun", R.create_from_sun_format), ("nyu", R.create_from_nyu_format)):
        depth = np.asarray(f(color, o3d.geometry.Image(raw.copy())).depth)[0]
        print(f"{name}_raw_depth = {vec(depth)}")


def cloud_summary(name, pc):
    pts = np.asarray(pc.points)
    print(f"{name}_count = {len(pts)}")
    print(f"{name}_centroid = {vec(pts.mean(axis=0))}")
    for i in POINT_INDICES:
        if i < len(pts):
            print(f"{name}_point[{i}] = {vec(pts[i])}")
    if pc.has_colors():
        cols = np.asarray(pc.colors)
        print(f"{name}_color_mean = {vec(cols.mean(axis=0))}")
        for i in POINT_INDICES:
            if i < len(cols):
                print(f"{name}_color[{i}] = {vec(cols[i])}")


def projection(root):
    print("// ---- back-projection of RGBD/color/00000.jpg + depth/00000.png, PrimeSense default intrinsic")
    rgbd_dir = os.path.join(root, "open3d", "RGBD")
    color = o3d.io.read_image(os.path.join(rgbd_dir, "color", "00000.jpg"))
    depth = o3d.io.read_image(os.path.join(rgbd_dir, "depth", "00000.png"))
    intr = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    R = o3d.geometry.RGBDImage
    P = o3d.geometry.PointCloud
    print("// create_from_color_and_depth defaults (intensity), create_from_rgbd_image")
    cloud_summary("rgbd_gray", P.create_from_rgbd_image(R.create_from_color_and_depth(color, depth), intr))
    print("// convert_rgb_to_intensity=False")
    rgbd = R.create_from_color_and_depth(color, depth, convert_rgb_to_intensity=False)
    cloud_summary("rgbd_rgb", P.create_from_rgbd_image(rgbd, intr))
    organised = P.create_from_rgbd_image(rgbd, intr, project_valid_depth_only=False)
    print(f"rgbd_organised_count = {len(organised.points)}  // NaN: "
          f"{int(np.isnan(np.asarray(organised.points)[:, 0]).sum())}")
    print("// create_from_depth_image(depth png, depth_scale 1000, depth_trunc 1000)")
    cloud_summary("depth", P.create_from_depth_image(depth, intr))
    traj = o3d.io.read_pinhole_camera_trajectory(os.path.join(rgbd_dir, "trajectory.log"))
    print("// create_from_depth_image(depth png, extrinsic = trajectory.log pose 0, depth_trunc 3.0, stride 2)")
    cloud_summary("depth_posed", P.create_from_depth_image(depth, intr, traj.parameters[0].extrinsic,
                                                           depth_scale=1000.0, depth_trunc=3.0, stride=2))


def main():
    root = data_root()
    print(f"// Open3D {o3d.__version__}")
    camera(root)
    datasets(root)
    raw_mappings()
    projection(root)


if __name__ == "__main__":
    main()
