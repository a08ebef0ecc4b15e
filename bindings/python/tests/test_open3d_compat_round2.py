"""An Open3D-style script over boxes, hulls, line sets, voxel grids, octrees and covariances runs unchanged
with `o3d` as `open3d` and gives Open3D's results.

The script is compat_scripts/round2_tutorial.py; the expected dict is what Open3D 0.20.0 produced for it
(tools/reference/record_python_round2.py, last line).
"""
import pathlib

import numpy as np

import o3d

SCRIPT = pathlib.Path(__file__).resolve().parent / "compat_scripts" / "round2_tutorial.py"

OPEN3D_RESULT = {
    "obb": (9.230943, 47, 47),
    "hull": (48, 92, 138, [1, 2, 6, 13, 16], 6.599893),
    "lines": (8, 12, [1.0, 0.0, 0.0]),
    "voxels": (241, 300),
    "octree": (4.008427, 4, True),
    "covariances": ((300, 3, 3), 46.703053),
    "hpr": 152,
}


def test_round2_tutorial_matches_open3d():
    ns = {"open3d": o3d, "np": np, "result": {}}
    exec(compile(SCRIPT.read_text(), str(SCRIPT), "exec"), ns)
    assert ns["result"] == OPEN3D_RESULT
