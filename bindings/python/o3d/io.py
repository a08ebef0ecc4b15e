"""o3d.io: reading and writing point clouds (ply, pcd, xyz, xyzn, xyzrgb, pts), triangle meshes (ply, obj,
stl, off, gltf, glb), images (png, jpg, ppm, pgm), camera models (JSON, .log), registration features (Open3D's
binary layout) and pose graphs (Open3D's JSON), to files or bytes.

Every reader raises on failure (``O3DFileNotFoundError``, ``O3DIOError``, ``ParseError``,
``UnsupportedError``) where Open3D would print a warning and return an empty object.
"""
from ._o3d import (  # noqa: F401
    read_feature,
    read_pose_graph,
    write_feature,
    write_pose_graph,
    read_image,
    read_image_from_bytes,
    read_pinhole_camera_intrinsic,
    read_pinhole_camera_parameters,
    read_pinhole_camera_trajectory,
    read_point_cloud,
    read_point_cloud_from_bytes,
    read_triangle_mesh,
    read_triangle_mesh_from_bytes,
    write_image,
    write_image_to_bytes,
    write_pinhole_camera_intrinsic,
    write_pinhole_camera_parameters,
    write_pinhole_camera_trajectory,
    write_point_cloud,
    write_point_cloud_to_buffer,
    write_point_cloud_to_bytes,
    write_triangle_mesh,
    write_triangle_mesh_to_bytes,
)

__all__ = ["read_point_cloud", "write_point_cloud", "read_point_cloud_from_bytes", "write_point_cloud_to_bytes",
           "write_point_cloud_to_buffer", "read_triangle_mesh", "write_triangle_mesh",
           "read_triangle_mesh_from_bytes", "write_triangle_mesh_to_bytes", "read_image", "write_image",
           "read_image_from_bytes", "write_image_to_bytes", "read_pinhole_camera_intrinsic",
           "write_pinhole_camera_intrinsic", "read_pinhole_camera_parameters", "write_pinhole_camera_parameters",
           "read_pinhole_camera_trajectory", "write_pinhole_camera_trajectory", "read_feature", "write_feature",
           "read_pose_graph", "write_pose_graph"]
