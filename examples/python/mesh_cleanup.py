#!/usr/bin/env python3
"""Read a mesh, clean it up, sample points on it, write both.

usage: mesh_cleanup.py INPUT OUTPUT_MESH OUTPUT_CLOUD [NUMBER_OF_POINTS]

Clean-up: merge duplicated vertices, drop duplicated and degenerate triangles, non-manifold edges and
unreferenced vertices, then recompute vertex normals. Sampling: Poisson-disk, NUMBER_OF_POINTS points
(default 2000), seeded so the output is reproducible. Formats from the extensions.
"""
import sys
import time

import o3d


def main(argv):
    if len(argv) not in (4, 5):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    n_points = int(argv[4]) if len(argv) == 5 else 2000
    t0 = time.perf_counter()
    mesh = o3d.io.read_triangle_mesh(argv[1])
    before = (len(mesh.vertices), len(mesh.triangles))
    mesh.remove_duplicated_vertices()
    mesh.remove_duplicated_triangles()
    mesh.remove_degenerate_triangles()
    mesh.remove_non_manifold_edges()
    mesh.remove_unreferenced_vertices()
    mesh.compute_vertex_normals()
    pcd = mesh.sample_points_poisson_disk(number_of_points=n_points, seed=0)
    o3d.io.write_triangle_mesh(argv[2], mesh)
    o3d.io.write_point_cloud(argv[3], pcd)
    elapsed = time.perf_counter() - t0
    print(f"read {before[0]} vertices, {before[1]} triangles from {argv[1]}")
    print(f"cleaned: {len(mesh.vertices)} vertices, {len(mesh.triangles)} triangles, "
          f"area {mesh.get_surface_area():.6g}, watertight {mesh.is_watertight()}")
    print(f"sampled {len(pcd.points)} points with normals {pcd.has_normals()}")
    print(f"wrote {argv[2]} and {argv[3]} in {elapsed:.3f} s (o3d {o3d.__version__})")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
