"""o3d: 3D data processing with Open3D's Python vocabulary (``import o3d`` for ``import open3d as o3d``).

Submodules: :mod:`o3d.geometry`, :mod:`o3d.io`, :mod:`o3d.pipelines.registration`, :mod:`o3d.utility`,
:mod:`o3d.camera`, :mod:`o3d.visualization` (RenderOption and the offscreen renderer,
:mod:`o3d.visualization.rendering`), and placeholders :mod:`o3d.pipelines.odometry`,
:mod:`o3d.pipelines.integration`.

Errors: every failure raises a subclass of :class:`o3d.O3DError` (itself a ``RuntimeError``) whose
``str()`` is the library's message and whose ``status`` / ``status_name`` give the C status:

=====================================  ==============================================  ======================
exception                              also a                                          C status
=====================================  ==============================================  ======================
``InvalidArgumentError``               ``ValueError``                                  O3D_ERROR_INVALID_ARGUMENT
``O3DMemoryError``                     ``MemoryError``                                 O3D_ERROR_OUT_OF_MEMORY
``O3DIOError``                         ``OSError``                                     O3D_ERROR_IO
``O3DFileNotFoundError``               ``O3DIOError``, ``FileNotFoundError``           O3D_ERROR_IO, missing file
``ParseError``                         ``RuntimeError``                                O3D_ERROR_PARSE
``UnsupportedError``                   ``NotImplementedError``                         O3D_ERROR_UNSUPPORTED
``NotConvergedError``                  ``RuntimeError``                                O3D_ERROR_NOT_CONVERGED
``CancelledError``                     ``RuntimeError``                                O3D_ERROR_CANCELLED
``InternalError``                      ``RuntimeError``                                anything else
=====================================  ==============================================  ======================

Unlike Open3D, a failed read raises instead of returning an empty cloud.
"""
from . import _o3d
from ._o3d import (  # noqa: F401
    CancelledError,
    InternalError,
    InvalidArgumentError,
    NotConvergedError,
    O3DError,
    O3DFileNotFoundError,
    O3DIOError,
    O3DMemoryError,
    ParseError,
    UnsupportedError,
)

__version__ = _o3d._version()
version_info = _o3d._version_tuple()

from . import utility  # noqa: E402
from . import geometry  # noqa: E402
from . import io  # noqa: E402
from . import pipelines  # noqa: E402
from . import camera  # noqa: E402
from . import visualization  # noqa: E402

__all__ = [
    "__version__", "version_info", "utility", "geometry", "io", "pipelines", "camera", "visualization",
    "O3DError", "InvalidArgumentError", "O3DMemoryError", "O3DIOError", "O3DFileNotFoundError", "ParseError",
    "UnsupportedError", "NotConvergedError", "CancelledError", "InternalError",
]
