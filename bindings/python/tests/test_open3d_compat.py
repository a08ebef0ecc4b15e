import pytest
"""The Open3D tutorial snippet (Figure 1) runs unchanged with `import o3d`."""
import numpy as np

import o3d


def test_figure1_script(data_file, tmp_path):
    pcd = o3d.io.read_point_cloud(data_file("open3d/Feature/cloud_bin_0.pcd"))
    n_in = len(pcd.points)
    down = pcd.voxel_down_sample(voxel_size=0.05)
    down.estimate_normals(search_param=o3d.geometry.KDTreeSearchParamHybrid(radius=0.1, max_nn=30))
    out = str(tmp_path / "down.ply")
    assert o3d.io.write_point_cloud(out, down)
    assert 0 < len(down.points) < n_in
    normals = np.asarray(down.normals)
    assert normals.shape == (len(down.points), 3)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-6)
    back = o3d.io.read_point_cloud(out)
    np.testing.assert_array_equal(np.asarray(back.points), np.asarray(down.points))
    # voxel grid: no two output points closer than a voxel edge can make them (they are cell averages)
    extent = down.get_axis_aligned_bounding_box().get_extent()
    assert np.all(extent > 0.05)


def test_pairwise_icp_on_open3d_fragments(data_file):
    source = o3d.io.read_point_cloud(data_file("open3d/Feature/cloud_bin_0.pcd")).voxel_down_sample(0.05)
    target = o3d.io.read_point_cloud(data_file("open3d/Feature/cloud_bin_1.pcd")).voxel_down_sample(0.05)
    before = o3d.pipelines.registration.evaluate_registration(source, target, 0.05, np.identity(4))
    result = o3d.pipelines.registration.registration_icp(
        source, target, 0.05, np.identity(4),
        o3d.pipelines.registration.TransformationEstimationPointToPoint())
    # Reference: Open3D 0.20.0 on the same calls (2655 and 2467 points after down-sampling):
    # evaluate_registration fitness 0.7412429378531074, inlier_rmse 0.02592621918827117 (1968 pairs);
    # registration_icp fitness 0.7401129943502824, inlier_rmse 0.025440297335814713 (1965 pairs).
    assert len(source.points) == 2655 and len(target.points) == 2467
    assert before.fitness == pytest.approx(0.7412429378531074, abs=1e-9)
    assert before.inlier_rmse == pytest.approx(0.02592621918827117, abs=1e-9)
    assert len(result.correspondence_set) == 1965
    assert result.fitness == pytest.approx(0.7401129943502824, abs=1e-9)
    assert result.inlier_rmse == pytest.approx(0.025440297335814713, abs=1e-9)
    np.testing.assert_allclose(result.transformation[:3, 3], [0.02820896, -0.02269889, 0.02249137], atol=1e-6)
    R = result.transformation[:3, :3]
    np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-9)
