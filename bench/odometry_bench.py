#!/usr/bin/env python3
"""RGB-D odometry benchmark: o3d against Open3D's legacy compute_rgbd_odometry, each library in its own process.

    bench/.venv/bin/python bench/odometry_bench.py [--out FILE]

The frame pairs 0->1 .. 3->4 of Open3D's RGBD test data (640 x 480, PrimeSense intrinsics, default
OdometryOption), each term (color, hybrid); the median per pair over 5 runs after one warm-up, and the
translation each library finds for pair 0->1 (so that a fast wrong answer shows).
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time

import numpy as np

DATA = os.path.join(os.environ.get("O3D_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "shared",
                                                                 "data")), "open3d", "RGBD")


def run_library(which):
    lib = __import__(which)
    intrinsic = lib.camera.PinholeCameraIntrinsic(lib.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)

    def frame(i):
        color = lib.io.read_image(os.path.join(DATA, "color", f"{i:05d}.jpg"))
        depth = lib.io.read_image(os.path.join(DATA, "depth", f"{i:05d}.png"))
        return lib.geometry.RGBDImage.create_from_color_and_depth(color, depth)

    frames = [frame(i) for i in range(5)]
    odometry = lib.pipelines.odometry
    out = {}
    for name, jacobian in (("color", odometry.RGBDOdometryJacobianFromColorTerm()),
                           ("hybrid", odometry.RGBDOdometryJacobianFromHybridTerm())):
        times = []
        for i in range(4):
            call = lambda: odometry.compute_rgbd_odometry(frames[i], frames[i + 1], intrinsic, np.identity(4),  # noqa
                                                          jacobian, odometry.OdometryOption())
            ok, trans, _ = call()
            if not ok:
                raise RuntimeError(f"{which}: no odometry for pair {i}")
            if i == 0:
                out[name + "_t"] = [float(x) for x in trans[:3, 3]]
            for _ in range(5):
                t0 = time.perf_counter()
                call()
                times.append(time.perf_counter() - t0)
        out[name] = statistics.median(times)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=None, help="append the Markdown table to this file")
    ap.add_argument("--library", choices=("o3d", "open3d"), help=argparse.SUPPRESS)  # a child process
    args = ap.parse_args()
    if args.library:
        print(json.dumps(run_library(args.library)))
        return
    results, versions = {}, {}
    for which in ("o3d", "open3d"):
        child = subprocess.run([sys.executable, __file__, "--library", which], capture_output=True, text=True)
        if child.returncode != 0:
            raise SystemExit(child.stderr)
        results[which] = json.loads(child.stdout.strip().splitlines()[-1])
        versions[which] = subprocess.run([sys.executable, "-c", f"import {which}; print({which}.__version__)"],
                                         capture_output=True, text=True).stdout.strip()
    lines = ["", "## RGB-D odometry (`bench/odometry_bench.py`)", "",
             f"- Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; machine: {platform.machine()}, "
             f"{os.cpu_count()} logical CPUs; o3d {versions['o3d']}, open3d {versions['open3d']}",
             "- Open3D's RGBD test frames 0->1 .. 3->4 (640 x 480), default OdometryOption, median per pair of 5 runs "
             "each; each library in its own process. Ratio = Open3D time / o3d time.", "",
             "| row | o3d | Open3D legacy | o3d / Open3D | translation 0->1, o3d | translation 0->1, Open3D |",
             "|---|---:|---:|---:|---|---|"]
    for name, label in (("hybrid", "hybrid term"), ("color", "color term")):
        a, b = results["o3d"][name], results["open3d"][name]
        ta = ", ".join(f"{x:.5f}" for x in results["o3d"][name + "_t"])
        tb = ", ".join(f"{x:.5f}" for x in results["open3d"][name + "_t"])
        lines.append(f"| compute_rgbd_odometry, {label}, per frame pair | {1000 * a:.0f} ms | {1000 * b:.0f} ms | "
                     f"{b / a:.2f}x | ({ta}) | ({tb}) |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "a") as f:
            f.write(text)


if __name__ == "__main__":
    main()
