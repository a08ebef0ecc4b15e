"""An Open3D-style mesh / RGB-D script runs unchanged with `o3d` as `open3d` and gives Open3D's results.

The script is compat_scripts/geometry_tutorial.py; the expected dict is what Open3D 0.20.0 produced for it
(tools/reference/record_python_geometry.py, last line).
"""
import pathlib

import numpy as np

import o3d

SCRIPT = pathlib.Path(__file__).resolve().parent / "compat_scripts" / "geometry_tutorial.py"

OPEN3D_RESULT = {
    "box": (8, 12, 7.0, 1.0, True),
    "smooth": (98, 192, 5.564687482),
    "clusters": ([192, 1200], [5.564687482, 19.568515683]),
    "rgbd": (3072, [0.0, -0.0, 1.5], [0.784314, 0.784314, 0.784314]),
}


def test_geometry_tutorial_matches_open3d():
    ns = {"open3d": o3d, "np": np, "result": {}}
    exec(compile(SCRIPT.read_text(), str(SCRIPT), "exec"), ns)
    assert ns["result"] == OPEN3D_RESULT
