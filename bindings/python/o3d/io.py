"""o3d.io: reading and writing point clouds (ply, pcd, xyz, xyzn, xyzrgb, pts), to files or bytes.

``read_point_cloud`` raises on failure (``O3DFileNotFoundError``, ``O3DIOError``, ``ParseError``,
``UnsupportedError``) where Open3D would print a warning and return an empty cloud.
"""
from ._o3d import (  # noqa: F401
    read_point_cloud,
    read_point_cloud_from_bytes,
    write_point_cloud,
    write_point_cloud_to_buffer,
    write_point_cloud_to_bytes,
)

__all__ = ["read_point_cloud", "write_point_cloud", "read_point_cloud_from_bytes", "write_point_cloud_to_bytes",
           "write_point_cloud_to_buffer"]
