"""o3d.pipelines: registration (ICP, global registration, pose graphs), odometry (RGB-D), integration (TSDF
volumes), color_map (colour-map optimization) and reconstruction (the scene reconstruction system)."""
from . import registration  # noqa: F401
from . import odometry  # noqa: F401
from . import integration  # noqa: F401
from . import color_map  # noqa: F401
from . import reconstruction  # noqa: F401
