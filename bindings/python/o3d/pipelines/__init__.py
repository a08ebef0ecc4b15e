"""o3d.pipelines: registration (ICP, global registration, pose graphs), odometry (RGB-D) and integration (TSDF
volumes)."""
from . import registration  # noqa: F401
from . import odometry  # noqa: F401
from . import integration  # noqa: F401
