"""o3d.pipelines.reconstruction on the shared living-room frames, against Open3D's own reconstruction system.

The reduced run CI can afford: the first 40 frames in two fragments of 20 (Open3D's defaults otherwise). The
reference is tools/reference/reconstruction_two_fragments.json, recorded by tools/reference/record_reconstruction.py
(Open3D 0.20's system restated on its API, integrating with its tensor VoxelBlockGrid because its legacy
ScalableTSDFVolume extracts nothing here; no keyframe loop closures, as Open3D without OpenCV). With the loop
closures off too, o3d must give the same poses within millimetres and the same mesh size within 2%; with its
default loop closures, the poses stay within centimetres of Open3D's. Also: the command line resumes, progress
and cancelling, and errors. (The known-trajectory run is tests/capi/test_reconstruction.c.)
"""
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import o3d
from o3d.pipelines import reconstruction

REFERENCE = pathlib.Path(__file__).resolve().parents[3] / "tools" / "reference" / "reconstruction_two_fragments.json"
FRAMES = 40


def _frames_folder(data_file, root):
    """The first FRAMES shared frames, linked (not copied) into root/data in Open3D's layout."""
    first = pathlib.Path(data_file("livingroom1_clean_micro/image/00000.jpg")).parents[1]
    for sub, ext in (("image", "jpg"), ("depth", "png")):
        (root / "data" / sub).mkdir(parents=True)
        for k in range(FRAMES):
            (root / "data" / sub / f"{k:05d}.{ext}").symlink_to(first / sub / f"{k:05d}.{ext}")
    return root / "data"


def _config(root, data, name, **extra):
    return {"path_dataset": str(data), "path_output": str(root / name), "n_frames_per_fragment": 20, **extra}


def _poses(folder):
    trajectory = o3d.io.read_pinhole_camera_trajectory(str(folder / "scene" / "trajectory.log"))
    return [np.linalg.inv(p.extrinsic) for p in trajectory.parameters]


def _worst_difference(poses, reference):
    """Largest camera-centre distance (m) and rotation angle (degrees) between two pose lists."""
    metres = degrees = 0.0
    for a, b in zip(poses, reference):
        d = np.linalg.inv(a) @ b
        metres = max(metres, float(np.linalg.norm(a[:3, 3] - b[:3, 3])))
        cos = np.clip((np.trace(d[:3, :3]) - 1.0) / 2.0, -1.0, 1.0)
        degrees = max(degrees, float(np.degrees(np.arccos(cos))))
    return metres, degrees


@pytest.fixture(scope="module")
def livingroom(tmp_path_factory):
    root = tmp_path_factory.mktemp("reconstruction")
    env_root = os.environ.get("O3D_TEST_DATA")
    shared = pathlib.Path(env_root) if env_root else pathlib.Path(__file__).resolve().parents[4] / "shared" / "data"
    if not (shared / "livingroom1_clean_micro" / "image" / "00000.jpg").is_file():
        if os.environ.get("O3D_REQUIRE_TEST_DATA") == "1":
            pytest.fail("test data not found: livingroom1_clean_micro (set O3D_TEST_DATA)")
        pytest.skip("test data not found: livingroom1_clean_micro (set O3D_TEST_DATA)")
    data = _frames_folder(lambda rel: str(shared / rel), root)
    return root, data, json.loads(REFERENCE.read_text())


def test_same_poses_and_mesh_as_open3d(livingroom):
    root, data, reference = livingroom
    config = _config(root, data, "like_open3d", loop_closure_odometry=False)
    fractions = []
    seconds = reconstruction.run_system(config, print_progress=False, callback=lambda f: fractions.append(f))
    assert list(seconds) == ["make fragments", "register fragments", "refine registration", "integrate scene"]
    assert fractions[-1] == 1.0

    poses = _poses(root / "like_open3d")
    expected = [np.array(p).reshape(4, 4) for p in reference["poses_camera_to_world"]]
    assert len(poses) == len(expected) == FRAMES
    metres, degrees = _worst_difference(poses, expected)
    assert metres < 0.003 and degrees < 0.1, (metres, degrees)  # measured 0.7 mm, 0.02 degrees

    mesh = o3d.io.read_triangle_mesh(str(root / "like_open3d" / "scene" / "integrated.ply"))
    vertices = reference["scene_mesh"]["vertices"]
    assert abs(len(mesh.vertices) - vertices) < 0.02 * vertices  # measured 299,310 vs 300,127
    assert mesh.has_vertex_colors() and mesh.has_vertex_normals()


def test_loop_closures_stay_close_to_open3d(livingroom):
    root, data, reference = livingroom
    reconstruction.run_system(_config(root, data, "default"), print_progress=False)
    expected = [np.array(p).reshape(4, 4) for p in reference["poses_camera_to_world"]]
    metres, degrees = _worst_difference(_poses(root / "default"), expected)
    assert metres < 0.05 and degrees < 2.0, (metres, degrees)  # measured 2.5 cm, 1.1 degrees
    graph = o3d.io.read_pose_graph(str(root / "default" / "fragments" / "fragment_optimized_000.json"))
    assert sum(e.uncertain for e in graph.edges) >= 1  # keyframe loop closures were kept


def test_command_line_resumes(livingroom):
    root, data, _ = livingroom
    config = root / "like_open3d.json"
    config.write_text(json.dumps(_config(root, data, "like_open3d", loop_closure_odometry=False)))
    mesh = root / "like_open3d" / "scene" / "integrated.ply"
    before = mesh.stat().st_mtime_ns
    out = subprocess.run([sys.executable, "-m", "o3d.pipelines.reconstruction", "--config", str(config), "--make",
                          "--register", "--refine", "--integrate"], capture_output=True, text=True, check=True)
    assert "integrate scene:" in out.stdout
    assert mesh.stat().st_mtime_ns == before  # every output was on disk: nothing redone


def test_cancel_keeps_finished_outputs(livingroom):
    root, data, _ = livingroom
    config = _config(root, data, "like_open3d", loop_closure_odometry=False)
    with pytest.raises(o3d.CancelledError, match="make fragments"):
        reconstruction.make_fragments(config, resume=False, print_progress=False, callback=lambda f: True)
    assert (root / "like_open3d" / "fragments" / "fragment_001.ply").is_file()


def test_errors(tmp_path):
    with pytest.raises(TypeError):
        reconstruction.make_fragments(42)
    with pytest.raises(o3d.ParseError, match="voxel_size"):
        reconstruction.make_fragments({"path_dataset": str(tmp_path), "voxel_size": -1})
    with pytest.raises(o3d.O3DIOError, match="no image/, rgb/ or color/ folder"):
        reconstruction.make_fragments({"path_dataset": str(tmp_path)})
    for sub in ("image", "depth"):  # one (unread) frame: registration needs the frame count only
        (tmp_path / sub).mkdir()
        (tmp_path / sub / "00000.png").write_bytes(b"")
    with pytest.raises(o3d.O3DIOError, match='run the "make fragments" stage first'):
        reconstruction.register_fragments({"path_dataset": str(tmp_path)}, print_progress=False)
    assert [s.name for s in reconstruction.ReconstructionStage.__members__.values()] == [
        "MakeFragments", "RegisterFragments", "RefineRegistration", "IntegrateScene", "ColorMap"]
