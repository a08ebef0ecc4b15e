#!/usr/bin/env python3
"""RGB-D frame -> coloured point cloud, as Open3D's RGBD tutorial.

usage: rgbd_to_point_cloud.py COLOR DEPTH OUTPUT [INTRINSIC_JSON]

COLOR is an 8-bit image, DEPTH a 16-bit depth image in millimetres (e.g. a frame of
livingroom1_clean_micro); INTRINSIC_JSON an Open3D PinholeCameraIntrinsic file (default: PrimeSense,
640x480, fx = fy = 525). The cloud is flipped to y-up, z-towards-the-viewer as in the tutorial, and
written to OUTPUT (format from the extension). Same code as Open3D's with `import o3d`.
"""
import sys
import time

import o3d


def main(argv):
    if len(argv) not in (4, 5):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    t0 = time.perf_counter()
    color = o3d.io.read_image(argv[1])
    depth = o3d.io.read_image(argv[2])
    rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth, convert_rgb_to_intensity=False)
    if len(argv) == 5:
        intrinsic = o3d.io.read_pinhole_camera_intrinsic(argv[4])
    else:
        intrinsic = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    pcd = o3d.geometry.PointCloud.create_from_rgbd_image(rgbd, intrinsic)
    pcd.transform([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]])
    o3d.io.write_point_cloud(argv[3], pcd)
    elapsed = time.perf_counter() - t0
    w, h = intrinsic.width, intrinsic.height
    print(f"rgbd {w}x{h} -> {len(pcd.points)} points with colors")
    print(f"center {pcd.get_center().round(4).tolist()}")
    print(f"wrote {argv[3]} in {elapsed:.3f} s (o3d {o3d.__version__})")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
