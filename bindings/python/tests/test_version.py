import re

import o3d


def test_version_string_matches_tuple():
    assert re.fullmatch(r"\d+\.\d+\.\d+.*", o3d.__version__)
    major, minor, patch = o3d.version_info
    assert o3d.__version__.startswith(f"{major}.{minor}.{patch}")


def test_placeholder_submodules_exist():
    import o3d.camera  # noqa: F401
    import o3d.pipelines.integration  # noqa: F401
    import o3d.pipelines.odometry  # noqa: F401
    import o3d.visualization  # noqa: F401

    assert o3d.pipelines.registration.registration_icp is not None
