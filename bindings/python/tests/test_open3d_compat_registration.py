"""Open3D's global-registration tutorial (RANSAC and FGR on FPFH, then point-to-plane refinement) runs
unchanged with `o3d` as `open3d` and gives Open3D's results.

The script is compat_scripts/global_registration_tutorial.py; the expected dict is what Open3D 0.20.0 produced
for it (tools/reference/record_python_registration.py, compat.result).
"""
import pathlib

import numpy as np

import o3d

SCRIPT = pathlib.Path(__file__).resolve().parent / "compat_scripts" / "global_registration_tutorial.py"

OPEN3D_RESULT = {"down": (2655, 2467), "fpfh": (33, 2655, 33, 2467), "ransac": True, "fgr": True, "icp": (True, 0.31)}


def test_global_registration_tutorial_matches_open3d(data_file):
    data = str(pathlib.Path(data_file("open3d/Feature/cloud_bin_0.pcd")).parents[1])
    ns = {"open3d": o3d, "np": np, "result": {}, "DATA": data}
    exec(compile(SCRIPT.read_text(), str(SCRIPT), "exec"), ns)
    assert ns["result"] == OPEN3D_RESULT
