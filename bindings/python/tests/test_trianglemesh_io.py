"""o3d.io.read_triangle_mesh / write_triangle_mesh (files and bytes): round trips per format, Open3D's
data files (numbers: tools/reference/record_python_geometry.py), keyword options, errors raise."""
import numpy as np
import pytest

import o3d

TM = o3d.geometry.TriangleMesh


def fp(a):
    a = np.asarray(a, dtype=np.float64).ravel()
    return float(((np.arange(a.size) + 1) * a).sum())


def colored_box():
    box = TM.create_box().compute_vertex_normals()
    box.vertex_colors = np.linspace(0, 1, 24).reshape(8, 3)
    return box


@pytest.mark.parametrize("ext", ["ply", "obj", "off", "stl", "glb", "gltf"])
def test_roundtrip_geometry(tmp_path, ext):
    box = colored_box()
    path = tmp_path / f"box.{ext}"
    assert o3d.io.write_triangle_mesh(str(path), box)
    back = o3d.io.read_triangle_mesh(path)
    assert len(back.triangles) == 12
    assert back.get_surface_area() == pytest.approx(6.0, rel=1e-6)
    if ext != "stl":  # STL stores triangle soups (each triangle its own three vertices)
        assert len(back.vertices) == 8


def test_ply_keeps_attributes_and_options(tmp_path):
    box = colored_box()
    path = str(tmp_path / "box.ply")
    o3d.io.write_triangle_mesh(path, box, write_ascii=True)
    assert open(path, "rb").read(3) == b"ply" and b"ascii" in open(path, "rb").read(40)
    back = o3d.io.read_triangle_mesh(path)
    np.testing.assert_allclose(np.asarray(back.vertices), np.asarray(box.vertices))
    np.testing.assert_array_equal(np.asarray(back.triangles), np.asarray(box.triangles))
    np.testing.assert_allclose(np.asarray(back.vertex_normals), np.asarray(box.vertex_normals), atol=1e-6)
    np.testing.assert_allclose(np.asarray(back.vertex_colors), np.asarray(box.vertex_colors), atol=1 / 255)
    o3d.io.write_triangle_mesh(path, box, write_vertex_normals=False, write_vertex_colors=False)
    bare = o3d.io.read_triangle_mesh(path)
    assert not bare.has_vertex_normals() and not bare.has_vertex_colors()


def test_bytes_roundtrip():
    box = colored_box()
    for fmt in ("ply", "stl", "off", "obj", "glb"):
        data = o3d.io.write_triangle_mesh_to_bytes(box, fmt)
        assert isinstance(data, bytes) and len(data) > 0
        back = o3d.io.read_triangle_mesh_from_bytes(data, fmt)
        assert back.get_surface_area() == pytest.approx(6.0, rel=1e-6), fmt


def test_post_processing_merges_duplicates(tmp_path):
    path = str(tmp_path / "box.stl")
    o3d.io.write_triangle_mesh(path, TM.create_box())
    assert len(o3d.io.read_triangle_mesh(path, enable_post_processing=True).vertices) == 8


def test_knot_matches_open3d(data_file):
    knot = o3d.io.read_triangle_mesh(data_file("open3d/knot.ply"))
    # Open3D 0.20: (1440, 2880), area 112072.277931022, watertight, Euler 0
    assert (len(knot.vertices), len(knot.triangles)) == (1440, 2880)
    assert knot.get_surface_area() == pytest.approx(112072.277931022, rel=1e-9)
    assert fp(knot.vertices) == pytest.approx(-392874830.38449365, rel=1e-9)
    assert fp(knot.triangles) == 35594024400.0
    assert knot.is_watertight() and knot.euler_poincare_characteristic() == 0


def test_textured_obj(data_file, tmp_path):
    crate = o3d.io.read_triangle_mesh(data_file("open3d/crate/crate.obj"))
    assert len(crate.triangles) > 0
    assert crate.has_triangle_uvs() and len(crate.triangle_uvs) == 3 * len(crate.triangles)
    assert crate.has_textures() and np.asarray(crate.textures[0]).ndim == 3
    out = tmp_path / "crate_copy.obj"
    o3d.io.write_triangle_mesh(str(out), crate)
    back = o3d.io.read_triangle_mesh(str(out))
    assert len(back.triangles) == len(crate.triangles) and back.has_textures()
    np.testing.assert_allclose(np.asarray(back.triangle_uvs), np.asarray(crate.triangle_uvs), atol=1e-6)


def test_errors_raise(tmp_path):
    with pytest.raises(FileNotFoundError):
        o3d.io.read_triangle_mesh(str(tmp_path / "missing.ply"))
    bad = tmp_path / "bad.ply"
    bad.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 100\nend_header\n\x00")
    with pytest.raises(o3d.O3DError):
        o3d.io.read_triangle_mesh(str(bad))
    with pytest.raises(NotImplementedError):
        o3d.io.write_triangle_mesh(str(tmp_path / "x.unknown"), TM.create_box())
    with pytest.raises(o3d.O3DError):
        o3d.io.read_triangle_mesh_from_bytes(b"garbage", "off")
