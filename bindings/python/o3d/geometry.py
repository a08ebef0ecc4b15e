"""o3d.geometry: PointCloud, TriangleMesh, Image, RGBDImage, KDTreeFlann, KDTreeSearchParam*,
AxisAlignedBoundingBox and the enums SimplificationContraction, FilterScope, ImageFilterType."""
import numpy as np

from ._o3d import (  # noqa: F401
    ColorToIntensityConversionType,
    FilterScope,
    Image,
    ImageFilterType,
    RGBDImage,
    SimplificationContraction,
    TriangleMesh,
    KDTreeFlann,
    KDTreeSearchParam,
    KDTreeSearchParamHybrid,
    KDTreeSearchParamKNN,
    KDTreeSearchParamRadius,
    PointCloud,
)


class AxisAlignedBoundingBox:
    """Box with faces parallel to the axes, given by its min and max corners (as Open3D's)."""

    def __init__(self, min_bound=(0.0, 0.0, 0.0), max_bound=(0.0, 0.0, 0.0)):
        self.min_bound = np.array(min_bound, dtype=np.float64).reshape(3)
        self.max_bound = np.array(max_bound, dtype=np.float64).reshape(3)
        self.color = np.zeros(3)

    def get_min_bound(self):
        return self.min_bound.copy()

    def get_max_bound(self):
        return self.max_bound.copy()

    def get_center(self):
        return (self.min_bound + self.max_bound) / 2.0

    def get_extent(self):
        return self.max_bound - self.min_bound

    def get_half_extent(self):
        return self.get_extent() / 2.0

    def get_max_extent(self):
        return float(np.max(self.get_extent()))

    def volume(self):
        return float(np.prod(self.get_extent()))

    def is_empty(self):
        return self.volume() <= 0.0

    def __repr__(self):
        return f"AxisAlignedBoundingBox: min: {tuple(self.min_bound)}, max: {tuple(self.max_bound)}"


def _point_cloud_from_ply(data):
    """Unpickle a PointCloud (binary PLY keeps points, normals and colors bit-exact)."""
    from ._o3d import read_point_cloud_from_bytes

    return read_point_cloud_from_bytes(data, "ply") if data else PointCloud()


def _point_cloud_reduce(self):
    from ._o3d import write_point_cloud_to_bytes

    return _point_cloud_from_ply, (write_point_cloud_to_bytes(self, "ply") if len(self) else b"",)


PointCloud.__reduce__ = _point_cloud_reduce


_MESH_ARRAYS = ("vertices", "vertex_normals", "vertex_colors", "triangles", "triangle_normals", "triangle_uvs",
                "triangle_material_ids")


def _triangle_mesh_from_state(arrays, textures):
    """Unpickle a TriangleMesh: every array and texture, bit-exact."""
    mesh = TriangleMesh()
    for name, value in zip(_MESH_ARRAYS, arrays):
        setattr(mesh, name, value)
    mesh.textures = textures
    return mesh


def _triangle_mesh_reduce(self):
    return _triangle_mesh_from_state, (tuple(np.array(getattr(self, n)) for n in _MESH_ARRAYS), self.textures)


TriangleMesh.__reduce__ = _triangle_mesh_reduce


def _image_reduce(self):
    return (Image, (np.array(self),)) if not self.is_empty() else (Image, ())


Image.__reduce__ = _image_reduce

__all__ = ["PointCloud", "TriangleMesh", "Image", "RGBDImage", "SimplificationContraction", "FilterScope",
           "ImageFilterType", "ColorToIntensityConversionType", "KDTreeFlann", "KDTreeSearchParam",
           "KDTreeSearchParamKNN", "KDTreeSearchParamRadius", "KDTreeSearchParamHybrid", "AxisAlignedBoundingBox"]
