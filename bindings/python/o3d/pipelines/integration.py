"""o3d.pipelines.integration: TSDF volumes (Open3D's UniformTSDFVolume and ScalableTSDFVolume): integrate RGB-D
frames, extract a mesh or points. Frames are RGBDImage.create_from_color_and_depth's output, with
convert_rgb_to_intensity=False for an RGB8 volume."""
from .._o3d import (  # noqa: F401
    ScalableTSDFVolume,
    TSDFVolume,
    TSDFVolumeColorType,
    UniformTSDFVolume,
)

__all__ = ["ScalableTSDFVolume", "TSDFVolume", "TSDFVolumeColorType", "UniformTSDFVolume"]
