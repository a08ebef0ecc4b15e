#!/usr/bin/env python3
"""The whole reconstruction system, stage by stage: o3d against Open3D's own system, in one run.

    bench/.venv/bin/python bench/reconstruction_bench.py [--frames N] [--out FILE]

The first N frames (default 211, all) of the shared livingroom1_clean_micro sequence with Open3D's default config
(3 fragments of 100 frames, voxel 0.05, TSDF voxel 3/512 m, colored ICP, RANSAC). Open3D's system is
tools/reference/record_reconstruction.py (its tutorial scripts restated on the 0.20 wheel; serial, as joblib is not
installed, and with its tensor VoxelBlockGrid where the legacy ScalableTSDFVolume extracts nothing). o3d runs
twice: as Open3D does without OpenCV (no keyframe loop closures, the like-for-like row) and with its defaults
(loop closures from the chained odometry: 2.6x the odometry pairs). Each run starts from empty output folders;
times are wall seconds per stage, each system in its own process.
"""
import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.environ.get("O3D_TEST_DATA", os.path.join(HERE, "..", "..", "shared", "data")),
                    "livingroom1_clean_micro")
STAGES = ["make", "register", "refine", "integrate"]
O3D_RUN = """
import json, sys, time
import o3d
from o3d.pipelines import reconstruction as r
config = json.load(open(sys.argv[1]))
seconds = {}
for name, stage in zip(%r, [r.ReconstructionStage.MakeFragments, r.ReconstructionStage.RegisterFragments,
                            r.ReconstructionStage.RefineRegistration, r.ReconstructionStage.IntegrateScene]):
    start = time.perf_counter()
    r.run_stage(config, stage, print_progress=False)
    seconds[name] = time.perf_counter() - start
mesh = o3d.io.read_triangle_mesh(config["path_output"] + "/scene/integrated.ply")
print(json.dumps({"seconds": seconds, "vertices": len(mesh.vertices)}))
""" % (STAGES,)


def frames_folder(root, n):
    """The first n frames linked into root/data (the system reads a folder)."""
    for sub, ext in (("image", "jpg"), ("depth", "png")):
        os.makedirs(os.path.join(root, "data", sub))
        for i in range(n):
            os.symlink(os.path.join(DATA, sub, f"{i:05d}.{ext}"), os.path.join(root, "data", sub, f"{i:05d}.{ext}"))
    return os.path.join(root, "data")


def run_o3d(root, data, name, extra):
    config = dict({"path_dataset": data, "path_output": os.path.join(root, name)}, **extra)
    path = os.path.join(root, name + ".json")
    with open(path, "w") as f:
        json.dump(config, f)
    out = subprocess.run([sys.executable, "-c", O3D_RUN, path], check=True, capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def run_open3d(root, data, n):
    config = {"path_dataset": data, "path_output": os.path.join(root, "open3d")}
    path = os.path.join(root, "open3d.json")
    with open(path, "w") as f:
        json.dump(config, f)
    summary = os.path.join(root, "open3d_summary.json")
    subprocess.run([sys.executable, os.path.join(HERE, "..", "tools", "reference", "record_reconstruction.py"),
                    "--config", path, "--make", "--register", "--refine", "--integrate", "--frames", str(n),
                    "--summary", summary], check=True, capture_output=True, text=True)
    with open(summary) as f:
        s = json.load(f)
    return {"seconds": s["seconds"], "vertices": s["scene_mesh"]["vertices"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frames", type=int, default=211)
    parser.add_argument("--out", help="write the results as JSON")
    args = parser.parse_args()
    import open3d
    import o3d
    with tempfile.TemporaryDirectory(prefix="o3d_reconstruction_bench_") as root:
        data = frames_folder(root, args.frames)
        results = {
            "open3d": run_open3d(root, data, args.frames),
            "o3d_like_open3d": run_o3d(root, data, "o3d_like_open3d", {"loop_closure_odometry": False}),
            "o3d_default": run_o3d(root, data, "o3d_default", {}),
        }
    print(f"# {args.frames} frames of livingroom1_clean_micro; {platform.processor() or platform.machine()}, "
          f"{os.cpu_count()} CPUs; Open3D {open3d.__version__}, o3d {o3d.__version__}")
    print(f"{'stage':<12}{'Open3D s':>10}{'o3d s':>10}{'ratio':>8}{'o3d+loops s':>13}{'ratio':>8}")
    total = {k: 0.0 for k in results}
    for stage in STAGES + ["total"]:
        if stage != "total":
            for k in results:
                total[k] += results[k]["seconds"][stage]
        row = {k: (total[k] if stage == "total" else results[k]["seconds"][stage]) for k in results}
        print(f"{stage:<12}{row['open3d']:>10.2f}{row['o3d_like_open3d']:>10.2f}"
              f"{row['open3d'] / row['o3d_like_open3d']:>7.1f}x{row['o3d_default']:>13.2f}"
              f"{row['open3d'] / row['o3d_default']:>7.1f}x")
    print("scene mesh vertices: " + ", ".join(f"{k} {v['vertices']:,}" for k, v in results.items()))
    if args.out:
        with open(args.out, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
