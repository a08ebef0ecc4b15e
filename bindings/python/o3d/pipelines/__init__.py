"""o3d.pipelines: registration (ICP); odometry and integration are placeholders."""
from . import registration  # noqa: F401
from . import odometry  # noqa: F401
from . import integration  # noqa: F401
