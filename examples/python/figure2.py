#!/usr/bin/env python3
"""Figure 2: a point cloud and a triangle mesh drawn together, the view rotating (10 px a frame).

usage: figure2.py CLOUD MESH [--frames N --out DIR]
Without --frames: a window (needs a display) until it is closed, as Open3D's
draw_geometries_with_animation_callback([cloud, mesh], rotate_view). With --frames N --out DIR: a hidden
window (no display needed) draws N frames and saves them as DIR/frame_%03d.png, printing their paths.
The mesh is scaled to a third of the cloud's size and placed at its centre, so that both are in view.
Same code as Open3D's tutorial with `import o3d` in place of `import open3d as o3d`.
"""
import argparse
import os
import sys

import numpy as np

import o3d


def load(cloud_path, mesh_path):
    cloud = o3d.io.read_point_cloud(cloud_path)
    mesh = o3d.io.read_triangle_mesh(mesh_path)
    mesh.compute_vertex_normals()
    mesh.paint_uniform_color([0.9, 0.6, 0.1])
    size = np.linalg.norm(cloud.get_max_bound() - cloud.get_min_bound())
    mesh_size = np.linalg.norm(mesh.get_max_bound() - mesh.get_min_bound())
    mesh.scale(size / (3 * mesh_size), center=mesh.get_center())
    mesh.translate(cloud.get_center(), relative=False)
    return [cloud, mesh]


def rotate_view(vis):
    vis.get_view_control().rotate(10.0, 0.0)
    return False


def save_frames(geometries, frames, out_dir):
    """Run a hidden window for `frames` frames, capturing each; returns the paths written."""
    vis = o3d.visualization.Visualizer()
    vis.create_window("Figure 2", 640, 480, visible=False)
    for geometry in geometries:
        vis.add_geometry(geometry)
    paths = []

    def capture_and_rotate(vis):
        paths.append(os.path.join(out_dir, f"frame_{len(paths):03d}.png"))
        vis.capture_screen_image(paths[-1])
        rotate_view(vis)
        if len(paths) == frames:
            vis.close()
        return True

    vis.register_animation_callback(capture_and_rotate)
    vis.run()
    vis.destroy_window()
    return paths


def main(argv):
    parser = argparse.ArgumentParser(usage=__doc__.strip().splitlines()[2].split(": ", 1)[1])
    parser.add_argument("cloud")
    parser.add_argument("mesh")
    parser.add_argument("--frames", type=int, help="draw N frames in a hidden window and save them (needs --out)")
    parser.add_argument("--out", help="folder for the saved frames")
    args = parser.parse_args(argv[1:])
    if (args.frames is None) != (args.out is None) or (args.frames is not None and args.frames < 1):
        parser.error("--frames N (N >= 1) and --out DIR go together")
    geometries = load(args.cloud, args.mesh)
    print(f"{len(geometries[0].points)} points, {len(geometries[1].triangles)} triangles")
    if args.frames is None:
        o3d.visualization.draw_geometries_with_animation_callback(geometries, rotate_view)
        return 0
    os.makedirs(args.out, exist_ok=True)
    for path in save_frames(geometries, args.frames, args.out):
        print(path)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
