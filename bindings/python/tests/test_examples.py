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


def test_rgbd_to_point_cloud_example(data_file, tmp_path):
    out = tmp_path / "frame.ply"
    run = subprocess.run([sys.executable, str(EXAMPLES / "rgbd_to_point_cloud.py"),
                          data_file("livingroom1_clean_micro/image/00000.jpg"),
                          data_file("livingroom1_clean_micro/depth/00000.png"), str(out)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    # Open3D 0.20 on the same frame (tools/reference/record_python_geometry.py): 300304 points
    assert "-> 300304 points with colors" in run.stdout
    import o3d

    pcd = o3d.io.read_point_cloud(str(out))
    assert len(pcd.points) == 300304 and pcd.has_colors()
    # the example flips y and z of Open3D's center (-0.003127767666863042, -0.06151389142611842, 1.770738728454002)
    import numpy as np

    np.testing.assert_allclose(pcd.get_center(), [-0.003127767666863042, 0.06151389142611842, -1.770738728454002],
                               rtol=1e-5)


def test_mesh_cleanup_example(data_file, tmp_path):
    mesh_out, cloud_out = tmp_path / "knot_clean.ply", tmp_path / "knot_points.ply"
    run = subprocess.run([sys.executable, str(EXAMPLES / "mesh_cleanup.py"), data_file("open3d/knot.ply"),
                          str(mesh_out), str(cloud_out), "500"], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "read 1440 vertices, 2880 triangles" in run.stdout
    assert "sampled 500 points with normals True" in run.stdout
    import o3d

    assert len(o3d.io.read_point_cloud(str(cloud_out)).points) == 500
    cleaned = o3d.io.read_triangle_mesh(str(mesh_out))
    assert len(cleaned.triangles) == 2880 and cleaned.has_vertex_normals()


def test_new_examples_usage_error():
    for name in ("rgbd_to_point_cloud.py", "mesh_cleanup.py"):
        run = subprocess.run([sys.executable, str(EXAMPLES / name)], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and "usage" in run.stderr.lower()
