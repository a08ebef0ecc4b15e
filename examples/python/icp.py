#!/usr/bin/env python3
"""Pairwise ICP: align SOURCE onto TARGET and print fitness, inlier RMSE and the transformation.

usage: icp.py SOURCE TARGET [MAX_CORRESPONDENCE_DISTANCE=0.05] [--point-to-plane] [--progress]
Both clouds are voxel-down-sampled at half the distance first.
"""
import sys

import numpy as np

import o3d

reg = o3d.pipelines.registration


def main(argv):
    flags = {a for a in argv[1:] if a.startswith("--")}
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) not in (2, 3) or not flags <= {"--point-to-plane", "--progress"}:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    distance = float(args[2]) if len(args) == 3 else 0.05
    source = o3d.io.read_point_cloud(args[0]).voxel_down_sample(distance / 2)
    target = o3d.io.read_point_cloud(args[1]).voxel_down_sample(distance / 2)
    if "--point-to-plane" in flags:
        target.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2 * distance, max_nn=30))
        method = reg.TransformationEstimationPointToPlane()
    else:
        method = reg.TransformationEstimationPointToPoint()
    before = reg.evaluate_registration(source, target, distance, np.identity(4))
    result = reg.registration_icp(source, target, distance, np.identity(4), method,
                                  reg.ICPConvergenceCriteria(max_iteration=50),
                                  print_progress="--progress" in flags)
    print(f"source {len(source.points)} points, target {len(target.points)} points, distance {distance}")
    print(f"before: fitness={before.fitness:.6f} inlier_rmse={before.inlier_rmse:.6f}")
    print(f"after:  fitness={result.fitness:.6f} inlier_rmse={result.inlier_rmse:.6f} "
          f"correspondences={len(result.correspondence_set)}")
    print("transformation:")
    print(np.array2string(result.transformation, precision=6, suppress_small=True))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
