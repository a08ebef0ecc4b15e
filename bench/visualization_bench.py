#!/usr/bin/env python3
"""Rendering benchmark: o3d's offscreen renderer against Open3D's legacy Visualizer, in one process.

    xvfb-run -a -s "-screen 0 1280x1024x24" bench/.venv/bin/python bench/visualization_bench.py [--out FILE]

Rows (each library draws the same geometry into a 640 x 480 image and reads it back, as a capture does):
- frames per second for a 1M-point colored cloud and for a 500k-triangle mesh with vertex normals:
  o3d's OffscreenRenderer.render_to_image (EGL; the GLFW backend too when a display is there),
  Open3D's Visualizer (a hidden window on the X display: poll_events + update_renderer +
  capture_screen_float_buffer(do_render=True));
- the time from the call to the first PNG written (renderer or window created, geometry added, one frame
  rendered and saved), for the 1M-point cloud.
Software rendering (Mesa llvmpipe) on a machine without a GPU: the report says which renderer each library got.
"""
import argparse
import os
import platform
import statistics
import sys
import tempfile
import time

import numpy as np

WIDTH, HEIGHT = 640, 480


def cloud_points(n=1_000_000, seed=3):
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-1, 1, size=(n, 2))
    z = 0.2 * np.sin(3 * xy[:, 0]) * np.cos(3 * xy[:, 1])
    pts = np.c_[xy, z]
    colors = (pts - pts.min(axis=0)) / np.ptp(pts, axis=0)
    return pts, colors


def fps(draw, frames, warmup=2):
    for _ in range(warmup):
        draw()
    times = []
    for _ in range(frames):
        t0 = time.perf_counter()
        draw()
        times.append(time.perf_counter() - t0)
    return 1.0 / statistics.median(times)


def o3d_rows(lib, points, colors, frames, backend):
    rendering = lib.visualization.rendering
    out = {}
    pcd = lib.geometry.PointCloud(lib.utility.Vector3dVector(points))
    pcd.colors = lib.utility.Vector3dVector(colors)
    mesh = lib.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=500)
    mesh.compute_vertex_normals()
    for name, geometry in (("cloud", pcd), ("mesh", mesh)):
        r = rendering.OffscreenRenderer(WIDTH, HEIGHT, backend=backend)
        material = rendering.MaterialRecord()
        material.point_size = 2
        r.scene.add_geometry(name, geometry, material)
        r.setup_camera_lookat([0, 0, 0], [0.3, -0.5, 1], [0, 1, 0], 0.8)
        out[name] = fps(r.render_to_image, frames)
        out["backend"] = r.backend
        del r
    path = os.path.join(tempfile.mkdtemp(), "first.png")
    t0 = time.perf_counter()
    r = rendering.OffscreenRenderer(WIDTH, HEIGHT, backend=backend)
    r.scene.add_geometry("cloud", pcd, rendering.MaterialRecord())
    r.render_to_png(path)
    out["first_png"] = time.perf_counter() - t0
    del r
    return out


def open3d_rows(o3d, points, colors, frames):
    out = {}
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    pcd.colors = o3d.utility.Vector3dVector(colors)
    mesh = o3d.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=500)
    mesh.compute_vertex_normals()
    for name, geometry in (("cloud", pcd), ("mesh", mesh)):
        vis = o3d.visualization.Visualizer()
        if not vis.create_window(width=WIDTH, height=HEIGHT, visible=False):
            raise RuntimeError("Open3D could not create a window (is DISPLAY set? run under xvfb-run)")
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
            vis.capture_screen_float_buffer(do_render=True)

        out[name] = fps(draw, frames)
        vis.destroy_window()
    path = os.path.join(tempfile.mkdtemp(), "first.png")
    t0 = time.perf_counter()
    vis = o3d.visualization.Visualizer()
    vis.create_window(width=WIDTH, height=HEIGHT, visible=False)
    vis.add_geometry(pcd)
    vis.capture_screen_image(path, do_render=True)
    out["first_png"] = time.perf_counter() - t0
    vis.destroy_window()
    if not os.path.exists(path):
        out["first_png"] = float("nan")
    return out


def gl_renderer_name():
    try:
        import subprocess
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
    args = ap.parse_args()

    import o3d
    import open3d

    points, colors = cloud_points()
    rows = {"o3d (EGL)": o3d_rows(o3d, points, colors, args.frames, "egl")}
    if os.environ.get("DISPLAY"):
        rows["o3d (GLFW, hidden window)"] = o3d_rows(o3d, points, colors, args.frames, "glfw")
    rows["Open3D legacy Visualizer (hidden window)"] = open3d_rows(open3d, points, colors, args.frames)
    base = rows["o3d (EGL)"]

    lines = [
        "## Rendering (`bench/visualization_bench.py`)",
        "",
        f"- Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; machine: {platform.processor() or platform.machine()}, "
        f"{os.cpu_count()} logical CPUs; o3d {o3d.__version__}, open3d {open3d.__version__}, python {platform.python_version()}",
        f"- Software rendering, no GPU: Mesa llvmpipe for both (X server: Xvfb; GL renderer: {gl_renderer_name()}).",
        f"- {WIDTH} x {HEIGHT}, point size 2; each frame renders and reads the image back; median of {args.frames} "
        "frames after 2 warm-up frames. Ratio = o3d (EGL) FPS / peer FPS, and peer time / o3d time for the first PNG.",
        "",
        "| row | " + " | ".join(rows) + " | o3d / Open3D |",
        "|---|" + "---:|" * (len(rows) + 1),
    ]
    peer = rows["Open3D legacy Visualizer (hidden window)"]
    for key, label in (("cloud", "FPS, 1M-point colored cloud"), ("mesh", "FPS, 500k-triangle mesh (vertex normals)")):
        lines.append(f"| {label} | " + " | ".join(f"{r[key]:.1f}" for r in rows.values()) +
                     f" | {base[key] / peer[key]:.2f}x |")
    lines.append("| call to first PNG, 1M-point cloud | " + " | ".join(f"{r['first_png'] * 1e3:.0f} ms" for r in rows.values()) +
                 f" | {peer['first_png'] / base['first_png']:.2f}x |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "a") as f:
            f.write("\n" + text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
