#!/usr/bin/env python3
"""Pictures of Poisson surface reconstruction on real data, o3d beside Open3D, rendered by o3d's offscreen renderer.

    python tools/make_surface_pictures.py [--out docs/images] [--data ../shared/data]

Needs the `o3d` package and the `open3d` wheel in one interpreter. Writes poisson_fragment.png: the shared
fragment.pcd meshed at depth 9 by o3d (left) and by Open3D 0.20 (right), each trimmed of its lowest-density 2% of
vertices as Open3D's tutorial does, and both drawn by o3d from the same viewpoint. Open3D's mesh only passes through
numpy arrays into an o3d TriangleMesh to be drawn.
"""
import argparse
import os

import numpy as np

import o3d


def trimmed(mesh_lib, mesh, densities, quantile=0.02):
    densities = np.asarray(densities)
    mesh.remove_vertices_by_mask(densities < np.quantile(densities, quantile))
    return mesh


def as_o3d(vertices, triangles, color, shift):
    mesh = o3d.geometry.TriangleMesh()
    mesh.vertices = o3d.utility.Vector3dVector(np.asarray(vertices) + shift)
    mesh.triangles = o3d.utility.Vector3iVector(np.asarray(triangles, dtype=np.int32))
    mesh.compute_vertex_normals()
    mesh.paint_uniform_color(color)
    return mesh


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="docs/images")
    ap.add_argument("--data", default=os.environ.get("O3D_TEST_DATA", "../shared/data"))
    ap.add_argument("--depth", type=int, default=9)
    args = ap.parse_args()
    import open3d

    path = os.path.join(args.data, "open3d", "fragment.pcd")
    mine = o3d.io.read_point_cloud(path)
    theirs = open3d.io.read_point_cloud(path)
    mesh, densities = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(mine, depth=args.depth)
    mesh = trimmed(o3d, mesh, densities)
    ref, ref_densities = open3d.geometry.TriangleMesh.create_from_point_cloud_poisson(theirs, depth=args.depth)
    ref = trimmed(open3d, ref, ref_densities)
    print(f"o3d: {len(mesh.vertices)} vertices, {len(mesh.triangles)} triangles; "
          f"Open3D: {len(ref.vertices)} vertices, {len(ref.triangles)} triangles (after the 2% trim)")

    lo, hi = mine.get_min_bound(), mine.get_max_bound()
    width = float(hi[0] - lo[0]) * 1.15
    left = as_o3d(mesh.vertices, mesh.triangles, [0.55, 0.7, 0.85], [0.0, 0.0, 0.0])
    right = as_o3d(ref.vertices, ref.triangles, [0.85, 0.7, 0.5], [width, 0.0, 0.0])
    center = (lo + hi) / 2 + [width / 2, 0.0, 0.0]
    eye = center + [0.0, -0.6 * width, 1.4 * width]

    rendering = o3d.visualization.rendering
    renderer = rendering.OffscreenRenderer(1200, 600)
    renderer.render_option.mesh_show_back_face = True
    for name, geometry in (("o3d", left), ("open3d", right)):
        renderer.scene.add_geometry(name, geometry, rendering.MaterialRecord())
    renderer.setup_camera(50.0, list(center), list(eye), [0.0, 0.0, 1.0])
    os.makedirs(args.out, exist_ok=True)
    out = os.path.join(args.out, "poisson_fragment.png")
    renderer.render_to_png(out)
    print(out)


if __name__ == "__main__":
    main()
