#!/usr/bin/env python3
"""Rendering benchmark: o3d against Open3D's legacy Visualizer, each library in its own process.

    xvfb-run -a -s "-screen 0 1280x1024x24" bench/.venv/bin/python bench/visualization_bench.py [--out FILE]

Both libraries draw the same geometry into a 640 x 480 frame and read it back, as a capture does:
- offscreen: o3d's OffscreenRenderer.render_to_image (EGL, no display); Open3D's Visualizer with a hidden
  window (its legacy viewer has no headless path);
- on screen: a visible Visualizer window on the X display (Xvfb), the same script for both libraries
  (poll_events + update_renderer + capture_screen_float_buffer(do_render=True));
- frames per second for a 1M-point colored cloud and a 1M-triangle sphere (create_sphere(resolution=500))
  with vertex normals, and the time from the call to the first PNG written (window or renderer created,
  the cloud added, one frame rendered and saved).
Each row of each library runs in a process of its own so that neither's OpenGL state can touch the other's, and every
timed frame is checked to show the geometry (enough non-background pixels), so an empty frame cannot pass
for a fast one. Software rendering (Mesa llvmpipe) on a machine without a GPU: the report says so.
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

WIDTH, HEIGHT = 640, 480
MIN_DRAWN_PIXELS = 5000


def cloud_points(n=1_000_000, seed=3):
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-1, 1, size=(n, 2))
    z = 0.2 * np.sin(3 * xy[:, 0]) * np.cos(3 * xy[:, 1])
    pts = np.c_[xy, z]
    colors = (pts - pts.min(axis=0)) / np.ptp(pts, axis=0)
    return pts, colors


def check_drawn(image):
    a = np.asarray(image, dtype=np.float64)
    a = a / 255.0 if a.max() > 1.0 else a
    drawn = int((a < 0.99).any(axis=2).sum())
    if drawn < MIN_DRAWN_PIXELS:
        raise RuntimeError(f"a timed frame shows only {drawn} drawn pixels: the geometry was not rendered")


def fps(draw, frames, warmup=2):
    for _ in range(warmup):
        check_drawn(draw())
    times = []
    for _ in range(frames):
        t0 = time.perf_counter()
        image = draw()
        times.append(time.perf_counter() - t0)
        check_drawn(image)
    return 1.0 / statistics.median(times)


def geometries(lib):
    points, colors = cloud_points()
    pcd = lib.geometry.PointCloud(lib.utility.Vector3dVector(points))
    pcd.colors = lib.utility.Vector3dVector(colors)
    mesh = lib.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=500)
    mesh.compute_vertex_normals()
    return {"cloud": pcd, "mesh": mesh}


def visualizer_rows(lib, geoms, frames, visible, row):
    """The same code for both libraries: their Visualizer APIs are the same."""
    out = {}
    for name, geometry in geoms.items():
        if name != row:
            continue
        vis = lib.visualization.Visualizer()
        if not vis.create_window(width=WIDTH, height=HEIGHT, visible=visible):
            raise RuntimeError("no window (is DISPLAY set? run under xvfb-run)")
        vis.add_geometry(geometry)
        vis.get_render_option().point_size = 2
        ctl = vis.get_view_control()
        ctl.set_lookat([0, 0, 0])
        ctl.set_front([0.3, -0.5, 1])
        ctl.set_up([0, 1, 0])
        ctl.set_zoom(0.8)

        def draw():
            vis.poll_events()
            vis.update_renderer()
            return vis.capture_screen_float_buffer(do_render=True)

        out[name] = fps(draw, frames)
        vis.destroy_window()
    if row != "first_png":
        return out
    path = os.path.join(tempfile.mkdtemp(), "first.png")
    t0 = time.perf_counter()
    vis = lib.visualization.Visualizer()
    vis.create_window(width=WIDTH, height=HEIGHT, visible=visible)
    vis.add_geometry(geoms["cloud"])
    vis.capture_screen_image(path, do_render=True)
    out["first_png"] = time.perf_counter() - t0
    vis.destroy_window()
    if not os.path.exists(path):
        raise RuntimeError("the first PNG was not written")
    return out


def o3d_offscreen_rows(lib, geoms, frames, row):
    rendering = lib.visualization.rendering
    out = {}
    for name, geometry in geoms.items():
        if name != row:
            continue
        r = rendering.OffscreenRenderer(WIDTH, HEIGHT, backend="egl")
        material = rendering.MaterialRecord()
        material.point_size = 2
        r.scene.add_geometry(name, geometry, material)
        r.setup_camera_lookat([0, 0, 0], [0.3, -0.5, 1], [0, 1, 0], 0.8)
        out[name] = fps(r.render_to_image, frames)
        del r
    if row != "first_png":
        return out
    path = os.path.join(tempfile.mkdtemp(), "first.png")
    t0 = time.perf_counter()
    r = rendering.OffscreenRenderer(WIDTH, HEIGHT, backend="egl")
    r.scene.add_geometry("cloud", geoms["cloud"], rendering.MaterialRecord())
    r.render_to_png(path)
    out["first_png"] = time.perf_counter() - t0
    return out


def run_library(which, mode, frames, row):
    lib = __import__("o3d" if which == "o3d" else "open3d")
    geoms = geometries(lib)
    if mode == "onscreen":
        return visualizer_rows(lib, geoms, frames, True, row)
    if which == "o3d":
        return o3d_offscreen_rows(lib, geoms, frames, row)
    return visualizer_rows(lib, geoms, frames, False, row)


def gl_renderer_name():
    try:
        text = subprocess.run(["glxinfo", "-B"], capture_output=True, text=True, timeout=10).stdout
        for line in text.splitlines():
            if "OpenGL renderer string" in line:
                return line.split(":", 1)[1].strip()
    except Exception:
        pass
    return "see EGL/GLX (Mesa llvmpipe on a machine without a GPU)"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--frames", type=int, default=15)
    ap.add_argument("--out", default=None, help="append the Markdown table to this file")
    ap.add_argument("--library", choices=("o3d", "open3d"), help=argparse.SUPPRESS)  # a child process
    ap.add_argument("--mode", choices=("offscreen", "onscreen"), help=argparse.SUPPRESS)
    ap.add_argument("--row", choices=("cloud", "mesh", "first_png"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.library:
        print(json.dumps(run_library(args.library, args.mode, args.frames, args.row)))
        return 0
    if not os.environ.get("DISPLAY"):
        sys.exit("the on-screen rows need an X display: run under xvfb-run")

    results = {"o3d": {}, "open3d": {}}
    versions = {}
    for which in ("o3d", "open3d"):
        for mode in ("offscreen", "onscreen"):
            results[which][mode] = {}
            # A process per row: Open3D's legacy viewer draws empty frames in a window opened after another
            # one was destroyed in the same process (seen here with 0.20), which a shared process would time.
            for row in ("cloud", "mesh", "first_png"):
                child = subprocess.run([sys.executable, __file__, "--library", which, "--mode", mode, "--row", row,
                                        "--frames", str(args.frames)], capture_output=True, text=True)
                if child.returncode != 0:
                    sys.exit(f"{which} {mode} {row} failed:\n{child.stderr[-2000:]}")
                results[which][mode].update(json.loads(child.stdout.strip().splitlines()[-1]))
        versions[which] = subprocess.run([sys.executable, "-c", f"import {which}; print({which}.__version__)"],
                                         capture_output=True, text=True).stdout.strip()
    mine, peer = results["o3d"], results["open3d"]
    lines = [
        "## Rendering (`bench/visualization_bench.py`)",
        "",
        f"- Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; machine: {platform.processor() or platform.machine()}, "
        f"{os.cpu_count()} logical CPUs; o3d {versions['o3d']}, open3d {versions['open3d']}, python {platform.python_version()}",
        f"- Software rendering, no GPU: Mesa llvmpipe for both (X server: Xvfb; GL renderer: {gl_renderer_name()}).",
        f"- {WIDTH} x {HEIGHT}, point size 2; each frame renders and reads the image back, and is checked to show the "
        f"geometry; median of {args.frames} frames after 2 warm-up frames; each library in its own process. "
        "Offscreen: o3d's OffscreenRenderer (EGL) against Open3D's hidden Visualizer window; on screen: a visible "
        "Visualizer window on Xvfb for both. Ratio = o3d FPS / Open3D FPS, and Open3D time / o3d time for the first PNG.",
        "",
        f"| row | o3d | Open3D {versions['open3d']} legacy | o3d / Open3D |",
        "|---|---:|---:|---:|",
    ]
    for mode, mode_label in (("offscreen", "offscreen"), ("onscreen", "on screen (Xvfb window)")):
        for key, label in (("cloud", "FPS, 1M-point colored cloud"), ("mesh", "FPS, 1M-triangle sphere (vertex normals)")):
            a, b = mine[mode][key], peer[mode][key]
            lines.append(f"| {label}, {mode_label} | {a:.1f} | {b:.1f} | {a / b:.2f}x |")
        a, b = mine[mode]["first_png"], peer[mode]["first_png"]
        lines.append(f"| call to first PNG, 1M-point cloud, {mode_label} | {a * 1e3:.0f} ms | {b * 1e3:.0f} ms | {b / a:.2f}x |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "a") as f:
            f.write("\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
