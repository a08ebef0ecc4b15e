"""examples/python scripts run and report what they did."""
import pathlib
import subprocess
import sys

EXAMPLES = pathlib.Path(__file__).resolve().parents[3] / "examples" / "python"


def test_figure1_example(data_file, tmp_path):
    out = tmp_path / "down.ply"
    run = subprocess.run([sys.executable, str(EXAMPLES / "figure1.py"), data_file("open3d/Feature/cloud_bin_0.pcd"),
                          str(out)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert out.stat().st_size > 0
    assert "normals" in run.stdout


def test_icp_example(data_file):
    run = subprocess.run([sys.executable, str(EXAMPLES / "icp.py"), data_file("open3d/Feature/cloud_bin_0.pcd"),
                          data_file("open3d/Feature/cloud_bin_1.pcd"), "0.05"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "fitness" in run.stdout and "inlier_rmse" in run.stdout


def test_example_usage_error():
    run = subprocess.run([sys.executable, str(EXAMPLES / "figure1.py")], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and "usage" in run.stderr.lower()
