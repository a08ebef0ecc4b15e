"""A short stretch of RGB-D reconstruction, as the paper's system starts it: RGB-D odometry between neighbouring
frames, the poses chained, every frame fused into a ScalableTSDFVolume, and the mesh extracted and rendered.

The frames are the shared living-room sequence when it is beside the checkout ($O3D_TEST_DATA or ../shared/data),
else frames synthesized here by ray casting a textured room with a ball in it (exact colour and depth).
Written as it would be for Open3D; only the import differs.
"""
import os

import numpy as np

import o3d

HERE = os.path.dirname(os.path.abspath(__file__))


def shared_sequence(n):
    root = os.environ.get("O3D_TEST_DATA") or os.path.join(HERE, "..", "..", "..", "shared", "data")
    folder = os.path.join(root, "livingroom1_clean_micro")
    if not os.path.isfile(os.path.join(folder, "depth", "00000.png")):
        return None
    intrinsic = o3d.camera.PinholeCameraIntrinsic(o3d.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
    frames = [(o3d.io.read_image(os.path.join(folder, "image", f"{i:05d}.jpg")),
               o3d.io.read_image(os.path.join(folder, "depth", f"{i:05d}.png"))) for i in range(n)]
    return "the shared living-room sequence", intrinsic, frames, 1000.0


def look_at(eye, target, up=(0.0, 0.0, 1.0)):
    forward = np.subtract(target, eye) / np.linalg.norm(np.subtract(target, eye))
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    down = np.cross(forward, right)
    extrinsic = np.identity(4)
    extrinsic[:3, :3] = np.vstack([right, down, forward])
    extrinsic[:3, 3] = -extrinsic[:3, :3] @ np.asarray(eye)
    return extrinsic


def ray_cast_room(eye, directions):
    """Depth along each ray inside a 4 x 3 x 2.5 m room with a 0.35 m ball on the floor, and a blotchy colour."""
    lo, hi = np.array([-2.0, -1.5, 0.0]), np.array([2.0, 1.5, 2.5])
    with np.errstate(divide="ignore", invalid="ignore"):
        exits = np.where(directions > 0, (hi - eye) / directions, (lo - eye) / directions)
    t = np.min(np.where(exits > 0, exits, np.inf), axis=1)
    centre, radius = np.array([0.6, 0.3, 0.35]), 0.35
    oc = eye - centre
    b = directions @ oc
    disc = b * b - (np.sum(directions ** 2, axis=1) * (oc @ oc - radius ** 2))
    ball = (-b - np.sqrt(np.maximum(disc, 0))) / np.sum(directions ** 2, axis=1)
    t = np.where((disc > 0) & (ball > 0) & (ball < t), ball, t)
    p = eye + t[:, None] * directions
    blotch = 0.5 + 0.3 * np.sin(6.0 * p[:, 0] + 2.0 * p[:, 2]) * np.cos(5.0 * p[:, 1] + 3.0 * p[:, 2])
    stripes = 0.15 * np.sin(17.0 * (p[:, 0] + p[:, 1] + p[:, 2]))
    colour = np.clip(np.c_[blotch + stripes, 0.8 * blotch, 0.6 * blotch - stripes] * 255, 0, 255)
    return t, colour


def synthesized_sequence(n):
    width, height, f = 320, 240, 260.0
    intrinsic = o3d.camera.PinholeCameraIntrinsic(width, height, f, f, 159.5, 119.5)
    u, v = np.meshgrid(np.arange(width), np.arange(height))
    rays = np.c_[((u - 159.5) / f).ravel(), ((v - 119.5) / f).ravel(), np.ones(u.size)]
    frames = []
    for i in range(n):
        angle = np.radians(-15 + 30 * i / max(n - 1, 1))
        eye = np.array([1.6 * np.cos(angle) - 0.1, 1.0 * np.sin(angle), 1.5])
        extrinsic = look_at(eye, [-1.5, 0.3 * np.sin(angle), 0.7])
        t, colour = ray_cast_room(eye, rays @ extrinsic[:3, :3])  # camera rays (unit z) turned into the room
        frames.append((o3d.geometry.Image(colour.reshape(height, width, 3).astype(np.uint8)),
                       o3d.geometry.Image(t.reshape(height, width).astype(np.float32))))
    return "frames o3d synthesized by ray casting a room", intrinsic, frames, 1.0


def reconstruct(frames, intrinsic, depth_scale, voxel_length, depth_trunc):
    odometry = o3d.pipelines.odometry
    integration = o3d.pipelines.integration
    volume = integration.ScalableTSDFVolume(voxel_length=voxel_length, sdf_trunc=5 * voxel_length,
                                            color_type=integration.TSDFVolumeColorType.RGB8)
    world_to_camera, previous = np.identity(4), None
    for color, depth in frames:
        gray = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth, depth_scale=depth_scale,
                                                                  depth_trunc=depth_trunc)
        rgb = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth, depth_scale=depth_scale,
                                                                 depth_trunc=depth_trunc, convert_rgb_to_intensity=False)
        if previous is not None:
            ok, step, _ = odometry.compute_rgbd_odometry(previous, gray, intrinsic, np.identity(4),
                                                         odometry.RGBDOdometryJacobianFromHybridTerm(),
                                                         odometry.OdometryOption())
            if ok:
                world_to_camera = step @ world_to_camera
        previous = gray
        volume.integrate(rgb, intrinsic, world_to_camera)
    mesh = volume.extract_triangle_mesh()
    mesh.compute_vertex_normals()
    return mesh, world_to_camera


def run(out_dir, step, render_png):
    source = shared_sequence(40) or synthesized_sequence(24)
    name, intrinsic, frames, depth_scale = source
    print(f"Reconstruction of a short stretch: {len(frames)} frames of {name}")
    shared = depth_scale == 1000.0  # (the room synthesized here is larger: a 4 m trunc sees its far wall)
    voxel, depth_trunc = (4.0 / 512, 3.0) if shared else (0.01, 4.5)
    mesh, last = step("odometry between neighbouring frames, each frame fused into a ScalableTSDFVolume, mesh extracted",
                      lambda: reconstruct(frames, intrinsic, depth_scale, voxel, depth_trunc))
    print(f"    {len(mesh.vertices):,} vertices, {len(mesh.triangles):,} triangles")
    mesh_path = os.path.join(out_dir, "room.ply")
    step(f"write_triangle_mesh({mesh_path})", lambda: o3d.io.write_triangle_mesh(mesh_path, mesh))
    # Seen from behind and above the first camera (the world frame is the first camera's: y down, z forward).
    centre = mesh.get_center()
    return step("rendered the reconstruction",
                lambda: render_png(os.path.join(out_dir, "room.png"), [("room", mesh, 1)],
                                   eye=[centre[0], centre[1] - 0.7, centre[2] - 2.4], center=centre, up=[0, -1, 0]))
