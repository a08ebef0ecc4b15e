"""Shared fixtures: test data lookup (O3D_TEST_DATA / O3D_REQUIRE_TEST_DATA) and small synthetic clouds."""
import os
import pathlib

import numpy as np
import pytest

REPO_ROOT = pathlib.Path(__file__).resolve().parents[3]


def _data_root():
    env = os.environ.get("O3D_TEST_DATA")
    return pathlib.Path(env) if env else (REPO_ROOT / ".." / "shared" / "data").resolve()


@pytest.fixture
def data_file():
    """data_file("open3d/Feature/cloud_bin_0.pcd") -> path; skips when missing, fails if O3D_REQUIRE_TEST_DATA=1."""

    def find(relative):
        path = _data_root() / relative
        if not path.is_file():
            message = f"test data not found: {path} (set O3D_TEST_DATA)"
            if os.environ.get("O3D_REQUIRE_TEST_DATA") == "1":
                pytest.fail(message)
            pytest.skip(message)
        return str(path)

    return find


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


@pytest.fixture
def plane_points(rng):
    """400 points on the plane z = 0.5 * x + 0.2 (jittered in x, y only)."""
    xy = rng.uniform(-1.0, 1.0, size=(400, 2))
    z = 0.5 * xy[:, 0] + 0.2
    return np.column_stack([xy, z])


@pytest.fixture
def random_points(rng):
    return rng.uniform(-1.0, 1.0, size=(500, 3))
