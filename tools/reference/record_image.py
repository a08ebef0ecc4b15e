#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Print Open3D's image numbers on the shared data, for tests/core/image_ops_test.cpp,
tests/core/image_io_test.cpp and tests/capi/test_image.c.

Usage (throwaway venv; Open3D is never a dependency of o3d):
    python3 -m venv /tmp/o3dref && /tmp/o3dref/bin/pip install open3d numpy
    /tmp/o3dref/bin/python tools/reference/record_image.py [DATA_ROOT]
DATA_ROOT defaults to $O3D_TEST_DATA or ../shared/data beside the checkout.

Open3D's Python API has no create_float_image / convert_depth_to_float: both are reached through
RGBDImage.create_from_color_and_depth (color -> Weighted float intensity, depth -> metres, truncated).
"""
import os
import sys

import numpy as np
import open3d as o3d

DEPTH_SCALE = 1000.0
DEPTH_TRUNC = 3.0
# (u, v) pixels: corners and edges (border replication) and a few interior ones.
PIXELS = [(0, 0), (639, 0), (0, 479), (639, 479), (320, 240), (100, 200), (1, 1), (600, 30)]
FILTERS = [
    ("Gaussian3", o3d.geometry.ImageFilterType.Gaussian3),
    ("Gaussian5", o3d.geometry.ImageFilterType.Gaussian5),
    ("Gaussian7", o3d.geometry.ImageFilterType.Gaussian7),
    ("Sobel3Dx", o3d.geometry.ImageFilterType.Sobel3dx),
    ("Sobel3Dy", o3d.geometry.ImageFilterType.Sobel3dy),
]


def data_root():
    if len(sys.argv) > 1:
        return sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("O3D_TEST_DATA", os.path.join(here, "..", "..", "..", "shared", "data"))


def floats(values):
    return "{" + ", ".join(f"{float(v):.9g}f" for v in values) + "}"


def at(a, pixels):
    return [a[v, u] for (u, v) in pixels]


def main():
    root = data_root()
    rgbd_dir = os.path.join(root, "open3d", "RGBD")
    print(f"// Open3D {o3d.__version__}")

    color = o3d.io.read_image(os.path.join(rgbd_dir, "color", "00000.jpg"))
    depth = o3d.io.read_image(os.path.join(rgbd_dir, "depth", "00000.png"))
    c = np.asarray(color)
    d = np.asarray(depth)
    print(f"// color/00000.jpg: {c.shape} {c.dtype}; depth/00000.png: {d.shape} {d.dtype}")
    print("// pixels (u, v):", PIXELS)
    print("color RGB:", [tuple(int(x) for x in c[v, u]) for (u, v) in PIXELS])
    print("color byte sum:", int(c.astype(np.int64).sum()))
    print("depth:", [int(d[v, u]) for (u, v) in PIXELS])
    print("depth sum:", int(d.astype(np.int64).sum()))

    rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(
        color, depth, depth_scale=DEPTH_SCALE, depth_trunc=DEPTH_TRUNC, convert_rgb_to_intensity=True)
    gray = np.asarray(rgbd.color)
    metres = np.asarray(rgbd.depth)
    print("intensity (Weighted):", floats(at(gray, PIXELS)), "sum", repr(float(gray.astype(np.float64).sum())))
    print("depth metres:", floats(at(metres, PIXELS)), "sum", repr(float(metres.astype(np.float64).sum())))

    for name, source in (("depth", rgbd.depth), ("intensity", rgbd.color)):
        for fname, ftype in FILTERS:
            f = np.asarray(source.filter(ftype))
            print(f"{name} {fname}:", floats(at(f, PIXELS)), "sum", repr(float(f.astype(np.float64).sum())))
        pyramid = source.create_pyramid(2, False)
        half = np.asarray(pyramid[1])
        print(f"{name} downsample {half.shape}:", floats(at(half, [(0, 0), (319, 239), (160, 120), (50, 100)])),
              "sum", repr(float(half.astype(np.float64).sum())))

    # Truncation at exactly depth_trunc, and the scale's float rounding.
    raw = np.array([[0, 1, 2999, 3000, 3001, 65535, 1234, 777]], dtype=np.uint16)
    tiny_color = o3d.geometry.Image(np.zeros((1, raw.shape[1], 3), dtype=np.uint8))
    r = o3d.geometry.RGBDImage.create_from_color_and_depth(
        tiny_color, o3d.geometry.Image(raw), depth_scale=DEPTH_SCALE, depth_trunc=DEPTH_TRUNC)
    print("depth", raw.tolist()[0], "->", floats(np.asarray(r.depth)[0]))

    # Odd sizes: Open3D's pyramid step keeps floor(size / 2).
    odd = o3d.geometry.Image(np.arange(35, dtype=np.float32).reshape(5, 7))
    print("odd 7x5 downsample:", np.asarray(odd.create_pyramid(2, False)[1]).tolist())

    # Every image under RGBD: size, channels, bit depth as Open3D reads them.
    for sub in ("color", "depth", "other_formats"):
        for name in sorted(os.listdir(os.path.join(rgbd_dir, sub))):
            if not name.endswith((".png", ".jpg")):
                continue
            a = np.asarray(o3d.io.read_image(os.path.join(rgbd_dir, sub, name)))
            ch = 1 if a.ndim == 2 else a.shape[2]
            print(f'{{"{sub}/{name}", {a.shape[1]}, {a.shape[0]}, {ch}, {a.dtype.itemsize}, {int(a.astype(np.int64).sum())}}},')


if __name__ == "__main__":
    main()
