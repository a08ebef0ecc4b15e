"""o3d.utility: containers (Vector3dVector, ...), verbosity, log callback, thread count, and
``o3d.utility.random.seed`` (the global generator of RANSAC and FGR).

The containers exist for Open3D compatibility: anything accepting them also accepts numpy arrays,
and ``np.asarray(v)`` is a zero-copy view of the container's data. Functions that Open3D gives as
IntVector/DoubleVector (KDTreeFlann searches, distances) return numpy arrays here.
"""
import atexit
import enum
import sys
import types

import numpy as np

from . import _o3d
from ._o3d import get_num_threads, set_num_threads  # noqa: F401


class _Vector:
    """A growable numpy-backed sequence; np.asarray() of it is a view of its data."""

    _dtypes = (np.float64,)  # accepted as is; anything else is converted to _dtypes[0]
    _cols = None  # None: 1-D; else rows of _cols values

    def __init__(self, data=None):
        if data is None:
            shape = (0,) if self._cols is None else (0, self._cols)
            self._data = np.empty(shape, dtype=self._dtypes[0])
            return
        if isinstance(data, _Vector):
            data = data._data
        arr = np.asarray(data)
        dtype = arr.dtype if any(arr.dtype == d for d in self._dtypes) else self._dtypes[0]
        if arr.dtype.kind not in "fiub":
            raise ValueError(f"{type(self).__name__}: expected numbers, got dtype {arr.dtype}")
        arr = np.array(arr, dtype=dtype, order="C", copy=True)
        self._data = self._check(arr)

    def _check(self, arr):
        if self._cols is None:
            if arr.size == 0:
                return arr.reshape(0)
            if arr.ndim != 1:
                raise ValueError(f"{type(self).__name__}: expected a 1-D sequence, got shape {arr.shape}")
        else:
            if arr.size == 0:
                return arr.reshape(0, self._cols)
            if arr.ndim != 2 or arr.shape[1] != self._cols:
                raise ValueError(f"{type(self).__name__}: expected shape (N, {self._cols}), got {arr.shape}")
        return arr

    def __array__(self, dtype=None, copy=None):
        if dtype is not None and np.dtype(dtype) != self._data.dtype:
            return self._data.astype(dtype)
        return self._data.copy() if copy else self._data

    def __len__(self):
        return len(self._data)

    def __getitem__(self, i):
        return self._data[i]

    def __setitem__(self, i, value):
        self._data[i] = value

    def __iter__(self):
        return iter(self._data)

    def __eq__(self, other):
        try:
            return np.array_equal(self._data, np.asarray(other))
        except Exception:
            return NotImplemented

    def append(self, value):
        row = np.asarray(value, dtype=self._data.dtype).reshape((1,) if self._cols is None else (1, self._cols))
        self._data = np.concatenate([self._data, row])

    def extend(self, values):
        other = type(self)(values)._data.astype(self._data.dtype)
        self._data = np.concatenate([self._data, other])

    def pop(self, i=-1):
        value = self._data[i].copy()
        self._data = np.delete(self._data, i, axis=0)
        return value

    def clear(self):
        self._data = self._data[:0].copy()

    def __repr__(self):
        return f"{type(self).__name__} with {len(self)} elements.\nUse numpy.asarray() to access data."


class Vector3dVector(_Vector):
    """(N, 3) points/normals/colors. Keeps float32 input as float32 (so a cloud takes it with one copy)."""

    _dtypes = (np.float64, np.float32)
    _cols = 3


class Vector3iVector(_Vector):
    """(N, 3) int32 (e.g. triangles)."""

    _dtypes = (np.int32,)
    _cols = 3


class Vector4iVector(_Vector):
    """(N, 4) int32 (e.g. a TetraMesh's tetras)."""

    _dtypes = (np.int32,)
    _cols = 4


class Vector2dVector(_Vector):
    """(N, 2) float64 (e.g. triangle UVs)."""

    _dtypes = (np.float64,)
    _cols = 2


class Vector2iVector(_Vector):
    """(N, 2) int32 (e.g. correspondences)."""

    _dtypes = (np.int32,)
    _cols = 2


class Matrix3dVector(_Vector):
    """(N, 3, 3) float64 (e.g. per-point covariances)."""

    _dtypes = (np.float64,)
    _cols = 3

    def __init__(self, data=None):
        super().__init__(data)
        self._data = self._check(self._data)

    def _check(self, arr):
        if arr.size == 0:
            return arr.reshape(0, 3, 3)
        if arr.ndim != 3 or arr.shape[1:] != (3, 3):
            raise ValueError(f"Matrix3dVector: expected shape (N, 3, 3), got {arr.shape}")
        return arr

    def append(self, value):
        self._data = np.concatenate([self._data, np.asarray(value, dtype=np.float64).reshape(1, 3, 3)])


class IntVector(_Vector):
    """1-D int32."""

    _dtypes = (np.int32,)


class DoubleVector(_Vector):
    """1-D float64."""

    _dtypes = (np.float64,)


class VerbosityLevel(enum.IntEnum):
    """Log levels, most severe first (values of the C O3D_LOG_* constants)."""

    Error = _o3d.O3D_LOG_ERROR
    Warning = _o3d.O3D_LOG_WARNING
    Info = _o3d.O3D_LOG_INFO
    Debug = _o3d.O3D_LOG_DEBUG


def set_verbosity_level(verbosity_level):
    """Show library messages at this level and more severe (default Warning)."""
    _o3d._set_verbosity_level(int(verbosity_level))


def get_verbosity_level():
    return VerbosityLevel(_o3d._get_verbosity_level())


def set_log_callback(callback):
    """Route library log lines to ``callback(level: VerbosityLevel, message: str)``; None restores stderr.

    The callback may run on a library worker thread (it holds the GIL while it runs); an exception
    it raises is reported as unraisable and otherwise ignored.
    """
    if callback is None:
        _o3d._set_log_callback(None)
        return
    if not callable(callback):
        raise TypeError("set_log_callback: expected a callable or None")

    def forward(level, message):
        callback(VerbosityLevel(level), message)

    _o3d._set_log_callback(forward)


class VerbosityContextManager:
    """``with VerbosityContextManager(VerbosityLevel.Debug): ...`` sets the level for a block."""

    def __init__(self, level):
        self.level = level

    def __enter__(self):
        self._old = get_verbosity_level()
        set_verbosity_level(self.level)
        return self

    def __exit__(self, *exc):
        set_verbosity_level(self._old)
        return False


def _seed(seed):
    """Seed the global generator that RANSAC and FGR draw from when not given a seed (Open3D's
    o3d.utility.random.seed). Without it the generator starts from a random device. Negative seeds wrap
    modulo 2**64."""
    _o3d._random_seed(seed)


random = types.ModuleType(__name__ + ".random", "Open3D's o3d.utility.random: seed(seed).")
_seed.__name__ = _seed.__qualname__ = "seed"
_seed.__module__ = random.__name__
random.seed = _seed
sys.modules[random.__name__] = random

# A Python callback must not be called once the interpreter is shutting down.
atexit.register(_o3d._set_log_callback, None)

__all__ = ["Vector3dVector", "Vector3iVector", "Vector4iVector", "Vector2dVector", "Vector2iVector", "Matrix3dVector",
           "IntVector", "DoubleVector", "VerbosityLevel",
           "VerbosityContextManager", "set_verbosity_level", "get_verbosity_level", "set_log_callback",
           "set_num_threads", "get_num_threads", "random"]
