"""o3d.camera: PinholeCameraIntrinsic, PinholeCameraIntrinsicParameters, PinholeCameraParameters,
PinholeCameraTrajectory (Open3D's names; read and write them with o3d.io)."""
from ._o3d import (  # noqa: F401
    PinholeCameraIntrinsic,
    PinholeCameraIntrinsicParameters,
    PinholeCameraParameters,
    PinholeCameraTrajectory,
)

__all__ = ["PinholeCameraIntrinsic", "PinholeCameraIntrinsicParameters", "PinholeCameraParameters",
           "PinholeCameraTrajectory"]
