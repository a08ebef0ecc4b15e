#!/usr/bin/env python3
"""Figure 1: read a cloud, voxel_down_sample(0.05), estimate normals (hybrid 0.1 / 30), write it.

usage: figure1.py INPUT OUTPUT        (any format o3d.io reads/writes, chosen by extension)
Same code as Open3D's tutorial with `import o3d` in place of `import open3d as o3d`.
"""
import sys
import time

import o3d


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    pcd = o3d.io.read_point_cloud(argv[1])
    down = pcd.voxel_down_sample(voxel_size=0.05)
    down.estimate_normals(search_param=o3d.geometry.KDTreeSearchParamHybrid(radius=0.1, max_nn=30))
    o3d.io.write_point_cloud(argv[2], down)
    elapsed = time.perf_counter() - t0
    print(f"read {len(pcd.points)} points from {argv[1]}")
    print(f"voxel_down_sample(0.05) -> {len(down.points)} points")
    print(f"estimate_normals(hybrid radius=0.1, max_nn=30) -> {len(down.normals)} normals")
    print(f"wrote {argv[2]} in {elapsed:.3f} s (o3d {o3d.__version__})")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
