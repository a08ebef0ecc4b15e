"""o3d.pipelines.odometry: RGB-D odometry (Open3D's compute_rgbd_odometry, OdometryOption and the color and
hybrid Jacobians). The frames are RGBDImage.create_from_color_and_depth's default output: float intensity and
depth in metres."""
from .._o3d import (  # noqa: F401
    OdometryOption,
    RGBDOdometryJacobian,
    RGBDOdometryJacobianFromColorTerm,
    RGBDOdometryJacobianFromHybridTerm,
    compute_rgbd_odometry,
)

__all__ = ["OdometryOption", "RGBDOdometryJacobian", "RGBDOdometryJacobianFromColorTerm",
           "RGBDOdometryJacobianFromHybridTerm", "compute_rgbd_odometry"]
