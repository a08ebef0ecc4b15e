#!/usr/bin/env python3
"""TSDF integration benchmark: o3d against Open3D's legacy integration, each library in its own process.

    bench/.venv/bin/python bench/tsdf_bench.py [--frames N] [--out FILE]

The first N frames (default 211, all) of the shared livingroom1_clean_micro sequence (640 x 480, PrimeSense
intrinsics, depth_trunc 3 m, RGB8), posed by o3d's own hybrid RGB-D odometry chained frame to frame (computed once,
untimed, and given to both libraries). Rows: integrate per frame into a ScalableTSDFVolume (voxel 4/512 m,
sdf_trunc 0.04), the median over the frames; extract_triangle_mesh of the whole room, the median of 3 runs.
Open3D 0.20's ScalableTSDFVolume extracts an empty mesh here, so its extraction row uses a UniformTSDFVolume on
the same voxel grid, 512^3 voxels placed over the room o3d found (its integration is timed in its own row).
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

DATA = os.path.join(os.environ.get("O3D_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "shared",
                                                                 "data")), "livingroom1_clean_micro")
VOXEL = 4.0 / 512


def frames(lib, n, intensity):
    for i in range(n):
        color = lib.io.read_image(os.path.join(DATA, "image", f"{i:05d}.jpg"))
        depth = lib.io.read_image(os.path.join(DATA, "depth", f"{i:05d}.png"))
        yield lib.geometry.RGBDImage.create_from_color_and_depth(color, depth, depth_trunc=3.0,
                                                                 convert_rgb_to_intensity=intensity)


def poses(n):
    """World-to-camera extrinsics from o3d's odometry, chained as Open3D's make_fragments does."""
    import o3d
    intrinsic = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    out, previous, world_to_camera = [], None, np.identity(4)
    for frame in frames(o3d, n, True):
        if previous is not None:
            ok, step, _ = o3d.pipelines.odometry.compute_rgbd_odometry(
                previous, frame, intrinsic, np.identity(4), o3d.pipelines.odometry.RGBDOdometryJacobianFromHybridTerm(),
                o3d.pipelines.odometry.OdometryOption())
            world_to_camera = step @ world_to_camera if ok else world_to_camera
        previous = frame
        out.append(world_to_camera.tolist())
    return out


def timed(call, repeat=1):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        value = call()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), value


def run_library(which, pose_file, uniform_origin):
    lib = __import__(which)
    integration = lib.pipelines.integration
    intrinsic = lib.camera.PinholeCameraIntrinsic(lib.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    extrinsics = [np.array(p) for p in json.load(open(pose_file))]
    images = list(frames(lib, len(extrinsics), False))
    out = {}
    volume = integration.ScalableTSDFVolume(voxel_length=VOXEL, sdf_trunc=0.04,
                                            color_type=integration.TSDFVolumeColorType.RGB8)
    per_frame = [timed(lambda: volume.integrate(image, intrinsic, e))[0] for image, e in zip(images, extrinsics)]
    out["integrate"] = statistics.median(per_frame)
    out["extract"], mesh = timed(volume.extract_triangle_mesh, 3)
    out["vertices"] = len(mesh.vertices)
    if which == "o3d":
        out["min_bound"] = np.asarray(mesh.vertices).min(axis=0).tolist()
        out["max_bound"] = np.asarray(mesh.vertices).max(axis=0).tolist()
    if uniform_origin is not None:
        uniform = integration.UniformTSDFVolume(length=4.0, resolution=512, sdf_trunc=0.04,
                                                color_type=integration.TSDFVolumeColorType.RGB8, origin=uniform_origin)
        for image, e in zip(images, extrinsics):
            uniform.integrate(image, intrinsic, e)
        out["uniform_extract"], mesh = timed(uniform.extract_triangle_mesh, 3)
        out["uniform_vertices"] = len(mesh.vertices)
    return out


def child(which, pose_file, origin=None):
    cmd = [sys.executable, __file__, "--library", which, "--poses", pose_file]
    if origin is not None:
        cmd += ["--origin", json.dumps(origin)]
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit(result.stderr)
    return json.loads(result.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--frames", type=int, default=211)
    ap.add_argument("--out", default=None, help="append the Markdown table to this file")
    ap.add_argument("--library", choices=("o3d", "open3d"), help=argparse.SUPPRESS)  # a child process
    ap.add_argument("--poses", help=argparse.SUPPRESS)
    ap.add_argument("--origin", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.library:
        origin = json.loads(args.origin) if args.origin else None
        print(json.dumps(run_library(args.library, args.poses, origin)))
        return
    with tempfile.TemporaryDirectory() as tmp:
        pose_file = os.path.join(tmp, "poses.json")
        with open(pose_file, "w") as f:
            json.dump(poses(args.frames), f)
        mine = child("o3d", pose_file)
        # 512^3 voxels from just below the room's corner, on the scalable volume's grid (multiples of a voxel).
        origin = [float(np.floor(x / VOXEL) * VOXEL - 0.1) for x in mine["min_bound"]]
        origin = [round(x / VOXEL) * VOXEL for x in origin]
        mine_uniform = child("o3d", pose_file, origin)
        theirs = child("open3d", pose_file, origin)
    versions = {w: subprocess.run([sys.executable, "-c", f"import {w}; print({w}.__version__)"], capture_output=True,
                                  text=True).stdout.strip() for w in ("o3d", "open3d")}
    extent = np.array(mine["max_bound"]) - np.array(mine["min_bound"])
    lines = ["", "## TSDF integration (`bench/tsdf_bench.py`)", "",
             f"- Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; machine: {platform.machine()}, "
             f"{os.cpu_count()} logical CPUs; o3d {versions['o3d']}, open3d {versions['open3d']}",
             f"- livingroom1_clean_micro, {args.frames} frames posed by o3d's odometry; the room o3d extracts spans "
             f"{extent[0]:.2f} x {extent[1]:.2f} x {extent[2]:.2f} m. Ratio = Open3D time / o3d time.", "",
             "| row | o3d | Open3D legacy | o3d / Open3D | vertices, o3d | vertices, Open3D |", "|---|---:|---:|---:|---:|---:|"]
    a, b = mine["integrate"], theirs["integrate"]
    lines.append(f"| ScalableTSDFVolume.integrate per frame (voxel 4/512 m, sdf_trunc 0.04, RGB8), median | "
                 f"{1000 * a:.1f} ms | {1000 * b:.1f} ms | {b / a:.2f}x | | |")
    a, b = mine["extract"], theirs["extract"]
    lines.append(f"| ScalableTSDFVolume.extract_triangle_mesh, whole room | {1000 * a:.0f} ms | {1000 * b:.0f} ms "
                 f"(empty mesh) | - | {mine['vertices']} | {theirs['vertices']} |")
    a, b = mine_uniform["uniform_extract"], theirs["uniform_extract"]
    lines.append(f"| UniformTSDFVolume(4 m, 512^3).extract_triangle_mesh over the room | {1000 * a:.0f} ms | "
                 f"{1000 * b:.0f} ms | {b / a:.2f}x | {mine_uniform['uniform_vertices']} | {theirs['uniform_vertices']} |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "a") as f:
            f.write(text)


if __name__ == "__main__":
    main()
