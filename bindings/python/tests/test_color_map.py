"""o3d.pipelines.color_map on tests/capi/test_color_map.c's scene, whose answer is known: a box room with a smooth
colour texture, ray-cast into five 8-bit RGB + float depth views of one corner, given with each pose turned by 1.5
degrees and moved about 2 cm. Both optimizers move the poses toward the truth and the colours toward the texture;
the GIL is released during the call; and the errors."""
import numpy as np
import pytest

import o3d
from test_gil import max_stall_during

color_map = o3d.pipelines.color_map
W, H = 160, 120
CAMERA = o3d.camera.PinholeCameraIntrinsic(W, H, 140.0, 140.0, 79.5, 59.5)
LO, HI = np.array([-1.2, -1.0, -1.0]), np.array([1.2, 1.0, 1.6])


def _texture(p):
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    return np.stack([0.5 + 0.2 * np.sin(5 * x + 2 * z) * np.cos(4 * y) + 0.15 * np.sin(11 * z + 3 * y),
                     0.5 + 0.2 * np.cos(4.5 * y + 1) * np.sin(5.5 * z - x) + 0.15 * np.cos(10 * x - 4 * y),
                     0.5 + 0.25 * np.sin(3 * (x + y + z)) + 0.15 * np.cos(12 * y - 5 * z + 3 * x)], axis=-1)


def _unit(v):
    return v / np.linalg.norm(v)


def _look_at(centre, target):
    """Camera-to-world pose at `centre` looking at `target` (world y points down)."""
    z = _unit(np.subtract(target, centre))
    x = _unit(np.cross([0, 1, 0], z))
    m = np.identity(4)
    m[:3, :3] = np.column_stack([x, np.cross(z, x), z])
    m[:3, 3] = centre
    return m


def _motion(axis, deg, t):
    """Rotation by `deg` about `axis` (Rodrigues), then translation t."""
    k, a = _unit(np.asarray(axis, float)), np.radians(deg)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    m = np.identity(4)
    m[:3, :3] = np.cos(a) * np.identity(3) + np.sin(a) * kx + (1 - np.cos(a)) * np.outer(k, k)
    m[:3, 3] = t
    return m


def _render(pose):
    """The RGB-D view from camera-to-world `pose`: each ray meets the room's box where it leaves it."""
    u, v = np.meshgrid(np.arange(W), np.arange(H))
    rays = np.stack([(u - 79.5) / 140.0, (v - 59.5) / 140.0, np.ones_like(u, dtype=float)], axis=-1) @ pose[:3, :3].T
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.min(np.where(rays != 0, (np.where(rays > 0, HI, LO) - pose[:3, 3]) / rays, np.inf), axis=-1)
    rgb = np.round(255 * _texture(pose[:3, 3] + t[..., None] * rays)).astype(np.uint8)
    depth = t.astype(np.float32)  # the camera ray has z = 1: t is the depth
    return o3d.geometry.RGBDImage.create_from_color_and_depth(
        o3d.geometry.Image(rgb), o3d.geometry.Image(depth), depth_scale=1.0, depth_trunc=10.0,
        convert_rgb_to_intensity=False)


@pytest.fixture(scope="module")
def scene():
    g = np.linspace(0, 1, 31)
    walls = []
    for axis in range(3):
        for side in (LO, HI):
            a, b = (axis + 1) % 3, (axis + 2) % 3
            p = np.zeros((31, 31, 3))
            p[..., axis] = side[axis]
            p[..., a] = LO[a] + (HI[a] - LO[a]) * g[None, :]
            p[..., b] = LO[b] + (HI[b] - LO[b]) * g[:, None]
            walls.append(p.reshape(-1, 3))
    mesh = o3d.geometry.TriangleMesh()
    mesh.vertices = o3d.utility.Vector3dVector(np.concatenate(walls))
    centres = [(0, 0, 0), (-0.6, -0.4, -0.5), (0.5, -0.5, 0.3), (-0.5, 0.5, 0.5), (0.4, 0.4, -0.6)]
    targets = [(1.2, 1.0, 1.6), (1.0, 1.0, 1.6), (1.2, 0.8, 1.6), (1.2, 1.0, 1.4), (1.1, 0.9, 1.5)]
    axes = [(1, 2, 0), (-1, 0, 2), (0, 1, 1), (2, -1, 1), (1, 1, -1)]
    shifts = [(0.02, -0.01, 0.01), (-0.01, 0.02, 0), (0, -0.02, -0.015), (0.015, 0.01, 0.01), (-0.02, 0, 0.01)]
    images, truth, start = [], [], o3d.camera.PinholeCameraTrajectory()
    params = []
    for c, t, ax, sh in zip(centres, targets, axes, shifts):
        pose = _look_at(c, t)
        images.append(_render(pose))
        truth.append(np.linalg.inv(pose))
        p = o3d.camera.PinholeCameraParameters()
        p.intrinsic = CAMERA
        p.extrinsic = _motion(ax, 1.5, sh) @ truth[-1]
        params.append(p)
    start.parameters = params
    return mesh, images, start, truth


def _pose_error(trajectory, truth):
    """Mean rotation error (degrees) and camera-centre distance (metres) against the truth."""
    deg, metres = [], []
    for p, t in zip(trajectory.parameters, truth):
        e = p.extrinsic @ np.linalg.inv(t)
        deg.append(np.degrees(np.arccos(np.clip((np.trace(e[:3, :3]) - 1) / 2, -1, 1))))
        metres.append(np.linalg.norm(np.linalg.inv(p.extrinsic)[:3, 3] - np.linalg.inv(t)[:3, 3]))
    return np.mean(deg), np.mean(metres)


def _color_error(mesh):
    """Mean RGB distance from the texture over the vertices within 1 m of the corner the cameras see."""
    xyz, rgb = np.asarray(mesh.vertices), np.asarray(mesh.vertex_colors)
    near = np.abs(xyz - HI).sum(axis=1) <= 1.0 + 1e-9
    assert near.sum() > 50
    return np.linalg.norm(rgb[near] - _texture(xyz[near]), axis=1).mean()


SCENE_OPTIONS = dict(maximum_allowable_depth=4.0, image_boundary_margin=4,
                     depth_threshold_for_discontinuity_check=1.0,  # slanted walls at 160 x 120 are no discontinuity
                     depth_threshold_for_visibility_check=0.2)  # the poses start a few cm off


def test_rigid_recovers_the_poses(scene):
    mesh, images, start, truth = scene
    mesh0, t0 = color_map.run_rigid_optimizer(mesh, images, start, color_map.RigidOptimizerOption(0, **SCENE_OPTIONS))
    option = color_map.RigidOptimizerOption(maximum_iteration=150, **SCENE_OPTIONS)
    result = {}
    stall, duration = max_stall_during(lambda: result.update(r=color_map.run_rigid_optimizer(mesh, images, start, option)))
    mesh1, t1 = result["r"]
    assert isinstance(mesh1, o3d.geometry.TriangleMesh) and isinstance(t1, o3d.camera.PinholeCameraTrajectory)
    (deg0, m0), (deg1, m1) = _pose_error(t0, truth), _pose_error(t1, truth)
    assert deg0 == pytest.approx(1.5, abs=1e-9)  # no iterations: the poses as given
    assert deg1 < 0.5 * deg0 and m1 < 0.6 * m0
    assert _color_error(mesh1) < 0.5 * _color_error(mesh0)
    assert not mesh.has_vertex_colors()  # the result is a copy
    assert stall < 0.5 * duration  # the GIL was released


def test_non_rigid_recovers_the_poses(scene):
    mesh, images, start, truth = scene
    option = color_map.NonRigidOptimizerOption(number_of_vertical_anchors=6, maximum_iteration=150, **SCENE_OPTIONS)
    assert option.non_rigid_anchor_point_weight == pytest.approx(0.316)  # the default kept
    colored, trajectory = color_map.run_non_rigid_optimizer(mesh, images, start, option)
    deg, m = _pose_error(trajectory, truth)
    assert deg < 0.75 and m < 0.015
    assert _color_error(colored) < 0.01  # from 0.055 at the given poses (the rigid optimizer reaches 0.005)


def test_options_and_errors(scene):
    mesh, images, start, _ = scene
    o = color_map.RigidOptimizerOption()
    assert (o.maximum_iteration, o.maximum_allowable_depth, o.invisible_vertex_color_knn) == (300, 2.5, 3)
    with pytest.raises(TypeError):
        color_map.RigidOptimizerOption(debug_output_dir="x")
    with pytest.raises(ValueError):  # fewer images than poses
        color_map.run_rigid_optimizer(mesh, images[:2], start, color_map.RigidOptimizerOption(1, **SCENE_OPTIONS))
    with pytest.raises(ValueError):
        color_map.run_non_rigid_optimizer(mesh, images, start, color_map.NonRigidOptimizerOption(1, maximum_iteration=1))
