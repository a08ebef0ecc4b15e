"""A short stretch of the paper's scene reconstruction system (o3d.pipelines.reconstruction, Open3D's
reconstruction_system): two fragments made by RGB-D odometry, loop closures and pose graphs, registered and refined
by colored ICP, every frame integrated into one TSDF, and the mesh rendered.

The frames are the shared living-room sequence when it is beside the checkout ($O3D_TEST_DATA or ../shared/data),
else frames synthesized here by ray casting a textured room with a ball in it (exact colour and depth), written to a
dataset folder as PNG files. The config is Open3D's reconstruction-system JSON layout.
"""
import os

import numpy as np

import o3d

HERE = os.path.dirname(os.path.abspath(__file__))


def shared_sequence(n, folder):
    """The first n shared frames linked (not copied) into folder/image and folder/depth; None when absent."""
    root = os.environ.get("O3D_TEST_DATA") or os.path.join(HERE, "..", "..", "..", "shared", "data")
    source = os.path.join(root, "livingroom1_clean_micro")
    if not os.path.isfile(os.path.join(source, "depth", "00000.png")):
        return None
    for sub, ext in (("image", "jpg"), ("depth", "png")):
        os.makedirs(os.path.join(folder, sub), exist_ok=True)
        for i in range(n):
            link = os.path.join(folder, sub, f"{i:05d}.{ext}")
            if not os.path.lexists(link):
                os.symlink(os.path.abspath(os.path.join(source, sub, f"{i:05d}.{ext}")), link)
    # Open3D's defaults (PrimeSense intrinsic, depth in millimetres, 3 m), two fragments.
    return "the shared living-room sequence", {"path_dataset": folder, "n_frames_per_fragment": n // 2}


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


def synthesized_sequence(n, folder):
    """n frames circling the room, written to folder/image and folder/depth (millimetres) with the intrinsic."""
    width, height, f = 320, 240, 260.0
    u, v = np.meshgrid(np.arange(width), np.arange(height))
    rays = np.c_[((u - 159.5) / f).ravel(), ((v - 119.5) / f).ravel(), np.ones(u.size)]
    for sub in ("image", "depth"):
        os.makedirs(os.path.join(folder, sub), exist_ok=True)
    for i, extrinsic in enumerate(synthesized_extrinsics(n)):
        eye = -extrinsic[:3, :3].T @ extrinsic[:3, 3]
        t, colour = ray_cast_room(eye, rays @ extrinsic[:3, :3])  # camera rays (unit z) turned into the room
        o3d.io.write_image(os.path.join(folder, "image", f"{i:05d}.png"),
                           o3d.geometry.Image(colour.reshape(height, width, 3).astype(np.uint8)))
        o3d.io.write_image(os.path.join(folder, "depth", f"{i:05d}.png"),
                           o3d.geometry.Image(np.round(t * 1000.0).reshape(height, width).astype(np.uint16)))
    intrinsic_path = os.path.join(folder, "intrinsic.json")
    o3d.io.write_pinhole_camera_intrinsic(intrinsic_path,
                                          o3d.camera.PinholeCameraIntrinsic(width, height, f, f, 159.5, 119.5))
    # The room is larger than the living room: a 4.5 m depth range sees its far wall; 1 cm TSDF voxels.
    return "frames o3d synthesized by ray casting a room", {
        "path_dataset": folder, "path_intrinsic": intrinsic_path, "depth_max": 4.5, "tsdf_cubic_size": 5.12,
        "n_frames_per_fragment": n // 2}


def synthesized_extrinsics(n):
    """World-to-camera poses of the synthesized frames: an arc looking across the room."""
    poses = []
    for i in range(n):
        angle = np.radians(-15 + 30 * i / max(n - 1, 1))
        eye = np.array([1.6 * np.cos(angle) - 0.1, 1.0 * np.sin(angle), 1.5])
        poses.append(look_at(eye, [-1.5, 0.3 * np.sin(angle), 0.7]))
    return poses


def reconstruct(config, out_dir):
    """The four stages of the system; returns the scene mesh and the camera-to-world poses (first camera's frame)."""
    config = dict(config, path_output=out_dir)
    o3d.pipelines.reconstruction.run_system(config, resume=False, print_progress=False)
    mesh = o3d.io.read_triangle_mesh(os.path.join(out_dir, "scene", "integrated.ply"))
    trajectory = o3d.io.read_pinhole_camera_trajectory(os.path.join(out_dir, "scene", "trajectory.log"))
    return mesh, [np.linalg.inv(p.extrinsic) for p in trajectory.parameters]


def run(out_dir, step, render_png):
    dataset = os.path.join(out_dir, "room_frames")
    name, config = shared_sequence(40, dataset) or synthesized_sequence(24, dataset)
    frames = len(os.listdir(os.path.join(dataset, "depth")))
    print(f"Reconstruction of a short stretch: {frames} frames of {name}")
    mesh, poses = step("the reconstruction system: make fragments (odometry, loop closures, pose graphs, TSDF), "
                       "register and refine them, integrate the scene",
                       lambda: reconstruct(config, os.path.join(out_dir, "room_reconstruction")))
    print(f"    {len(mesh.vertices):,} vertices, {len(mesh.triangles):,} triangles, {len(poses)} camera poses "
          f"(scene/integrated.ply, scene/trajectory.log)")
    # Seen from behind and above the first camera (the world frame is the first camera's: y down, z forward).
    centre = mesh.get_center()
    return step("rendered the reconstruction",
                lambda: render_png(os.path.join(out_dir, "room.png"), [("room", mesh, 1)],
                                   eye=[centre[0], centre[1] - 0.7, centre[2] - 2.4], center=centre, up=[0, -1, 0]))
