#!/usr/bin/env python3
"""The paper's scene reconstruction system on a folder of RGB-D frames, then a picture of the scene it built.

usage: reconstruction_system.py CONFIG.json [--picture SCENE.png] [--make] [--register] [--refine] [--integrate]

CONFIG.json is Open3D's reconstruction-system config (path_dataset with image/ and depth/, ...; o3d also reads
path_output). The stage flags are Open3D's run_system.py's (none: all four); each stage resumes from its outputs,
shows a progress bar, and Ctrl-C cancels it. --picture renders scene/integrated.ply with o3d's offscreen renderer
(no display needed), looking down into the scene from above the first camera.
"""
import argparse
import json
import os
import sys

import o3d
from o3d.pipelines import reconstruction


def render(mesh, path):
    rendering = o3d.visualization.rendering
    renderer = rendering.OffscreenRenderer(1000, 700)
    renderer.render_option.mesh_show_back_face = True
    renderer.scene.add_geometry("scene", mesh, rendering.MaterialRecord())
    # The scene is in the first camera's frame (x right, y down, z forward): look down and forward from above it.
    lo, hi = mesh.get_min_bound(), mesh.get_max_bound()
    centre = (lo + hi) / 2
    size = max(hi - lo)
    eye = [centre[0], centre[1] - 0.6 * size, centre[2] - 0.4 * size]
    renderer.setup_camera(60.0, centre, eye, [0, -1, 0])
    renderer.render_to_png(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("config")
    parser.add_argument("--picture")
    for stage in ("make", "register", "refine", "integrate"):
        parser.add_argument(f"--{stage}", action="store_true")
    args = parser.parse_args(argv)
    seconds = reconstruction.run_system(args.config, args.make, args.register, args.refine, args.integrate)
    for stage, s in seconds.items():
        print(f"{stage}: {s:.1f} s")
    with open(args.config) as f:
        config = json.load(f)
    scene = os.path.join(config.get("path_output") or config["path_dataset"], "scene")
    mesh = o3d.io.read_triangle_mesh(os.path.join(scene, "integrated.ply"))
    trajectory = o3d.io.read_pinhole_camera_trajectory(os.path.join(scene, "trajectory.log"))
    print(f"{len(mesh.vertices):,} vertices, {len(mesh.triangles):,} triangles, {len(trajectory.parameters)} poses")
    if args.picture:
        render(mesh, args.picture)
        print(f"wrote {args.picture}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
