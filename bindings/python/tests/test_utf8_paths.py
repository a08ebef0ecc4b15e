import numpy as np
import pytest

import o3d


@pytest.mark.parametrize("name", ["scan-été.ply", "点云.pcd", "скан данные.xyz"])
def test_utf8_file_names_round_trip(tmp_path, name):
    folder = tmp_path / "données 3D"
    folder.mkdir()
    pts = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, 3.0], [-4.5, 0.25, 8.0]])
    assert o3d.io.write_point_cloud(str(folder / name), o3d.geometry.PointCloud(pts))
    back = o3d.io.read_point_cloud(str(folder / name))
    np.testing.assert_allclose(np.asarray(back.points), pts, atol=1e-6)


def test_missing_utf8_path_names_the_file(tmp_path):
    with pytest.raises(FileNotFoundError, match="нет.ply"):
        o3d.io.read_point_cloud(str(tmp_path / "нет.ply"))
