#!/usr/bin/env python3
"""Surface reconstruction and the point-cloud algorithms of issue 22: o3d against Open3D, each (library, row) in a
fresh process, so that its peak memory is its own.

    bench/.venv/bin/python bench/surface_bench.py [--threads 2] [--repeat 3] [--out bench/RESULTS.md]
    bench/.venv/bin/python bench/surface_bench.py --accuracy [--out FILE]
    bench/.venv/bin/python bench/surface_bench.py --geometry [--out bench/RESULTS.md]   # the second half's rows

Rows (the issue's): screened Poisson at depth 8 and 10 on the shared fragment.pcd (its own normals); ball pivoting
and the alpha shape on a 50k-point uniform sampling of the shared knot mesh (normals from the mesh; radii 1.5x and
3x the mean spacing, alpha 4x it); orient_normals_consistent_tangent_plane(10) on fragment.pcd after
estimate_normals (KNN 30, untimed); ISS keypoints on fragment.pcd with Open3D's default radii. Each cell is the
median of --repeat runs after one warm-up; the input is built before timing. Peak memory: the growth of the
process's peak resident set (VmHWM, reset through /proc/self/clear_refs) during the first call, in a fresh process
whose input is already built.

--accuracy: both libraries' reconstructions of points sampled from known surfaces (a sphere of radius 1, a torus
(R 1, r 0.35) and the shared knot mesh; clean and with Gaussian noise of 0.5% of the size) against the true
surface: the two-sided distance (reconstruction -> truth from 100k points sampled on the reconstruction, truth ->
reconstruction: from the true samples to the reconstructed triangles, by Open3D's RaycastingScene), mean and 99th
percentile, relative to the bounding-box diagonal.
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time

import numpy as np

DATA = os.environ.get("O3D_TEST_DATA", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared",
                                                    "data"))
FRAGMENT = os.path.join(DATA, "open3d", "fragment.pcd")
KNOT = os.path.join(DATA, "open3d", "knot.ply")
ROWS = ["poisson_depth8", "poisson_depth10", "ball_pivoting", "alpha_shape", "orient_tangent_plane", "iss"]
# The geometry algorithms of issue 22's second half (run with --only, or all with --geometry).
GEOMETRY_ROWS = ["smooth_mls", "smooth_laplacian", "smooth_taubin", "smooth_bilateral", "estimate_point_covariances",
                 "detect_planar_patches", "minimal_obb", "oriented_bounding_ellipsoid", "voxel_down_sample_and_trace",
                 "filter_sharpen", "self_intersecting_triangles", "deform_arap", "half_edge_mesh"]


def peak_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return 0


def reset_peak():
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        return True
    except OSError:
        return False


def knot_samples(lib, n=50_000):
    mesh = lib.io.read_triangle_mesh(KNOT)
    mesh.compute_vertex_normals()
    # Uniform sampling with a fixed seed on each side is not the same points; the row compares like with like
    # by sampling once (with o3d) and handing both libraries the same arrays.
    return mesh.sample_points_uniformly(number_of_points=n, use_triangle_normal=True)


def setup(lib, row, shared):
    g = lib.geometry
    if row.startswith("poisson"):
        pcd = lib.io.read_point_cloud(FRAGMENT)
        depth = 8 if row.endswith("8") else 10
        return lambda: g.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=depth)
    if row in ("ball_pivoting", "alpha_shape"):
        pcd = g.PointCloud()
        pcd.points = lib.utility.Vector3dVector(shared["points"])
        pcd.normals = lib.utility.Vector3dVector(shared["normals"])
        spacing = shared["spacing"]
        if row == "ball_pivoting":
            radii = lib.utility.DoubleVector([1.5 * spacing, 3.0 * spacing])
            return lambda: g.TriangleMesh.create_from_point_cloud_ball_pivoting(pcd, radii)
        return lambda: g.TriangleMesh.create_from_point_cloud_alpha_shape(pcd, 4.0 * spacing)
    if row == "orient_tangent_plane":
        base = lib.io.read_point_cloud(FRAGMENT)
        base.estimate_normals(search_param=g.KDTreeSearchParamKNN(30))

        def run():
            pcd = g.PointCloud(base)
            pcd.orient_normals_consistent_tangent_plane(10)
            return pcd
        return run
    if row == "iss":
        pcd = lib.io.read_point_cloud(FRAGMENT)
        return lambda: g.keypoint.compute_iss_keypoints(pcd)
    return setup_geometry(lib, row)


def setup_geometry(lib, row):
    """The second-half rows: fragment.pcd for the point-cloud calls, the knot mesh for the mesh calls, a sphere of
    resolution 40 (3,122 vertices) for ARAP with its top cap moved and its bottom cap held."""
    g = lib.geometry
    if row in GEOMETRY_ROWS[:9]:  # the point-cloud rows
        pcd = lib.io.read_point_cloud(FRAGMENT)
        hybrid = g.KDTreeSearchParamHybrid(radius=0.05, max_nn=30)
        calls = {
            "smooth_mls": lambda: pcd.smooth_mls(hybrid),
            "smooth_laplacian": lambda: pcd.smooth_laplacian(iterations=10, lambda_=0.5, knn=20),
            "smooth_taubin": lambda: pcd.smooth_taubin(iterations=10, lambda_=0.5, mu=-0.53, knn=20),
            "smooth_bilateral": lambda: pcd.smooth_bilateral(hybrid, 0.05, 0.05),
            "estimate_point_covariances": lambda: g.PointCloud.estimate_point_covariances(
                pcd, g.KDTreeSearchParamKNN(30)),
            "detect_planar_patches": lambda: pcd.detect_planar_patches(),
            "minimal_obb": lambda: pcd.get_minimal_oriented_bounding_box(),
            "oriented_bounding_ellipsoid": lambda: pcd.get_oriented_bounding_ellipsoid(),
            "voxel_down_sample_and_trace": lambda: pcd.voxel_down_sample_and_trace(
                0.02, pcd.get_min_bound(), pcd.get_max_bound()),
        }
        return calls[row]
    mesh = lib.io.read_triangle_mesh(KNOT)
    if row == "filter_sharpen":
        return lambda: mesh.filter_sharpen(number_of_iterations=5, strength=0.1)
    if row == "self_intersecting_triangles":
        return lambda: mesh.get_self_intersecting_triangles()
    if row == "half_edge_mesh":
        clean = g.TriangleMesh.create_sphere(radius=1.0, resolution=80)
        return lambda: g.HalfEdgeTriangleMesh.create_from_triangle_mesh(clean)
    if row == "deform_arap":
        sphere = g.TriangleMesh.create_sphere(radius=1.0, resolution=40)
        v = np.asarray(sphere.vertices)
        top, bottom = np.where(v[:, 2] > 0.9)[0], np.where(v[:, 2] < -0.9)[0]
        ids = np.concatenate([top, bottom]).astype(np.int32)
        pos = np.concatenate([v[top] + [0.3, 0.0, 0.2], v[bottom]])
        return lambda: sphere.deform_as_rigid_as_possible(lib.utility.IntVector(ids), lib.utility.Vector3dVector(pos),
                                                          max_iter=10)
    raise SystemExit(f"unknown row {row}")


def describe(row, value):
    if row.startswith("poisson"):
        mesh = value[0]
        return f"{len(mesh.vertices)} v, {len(mesh.triangles)} t"
    if row in ("ball_pivoting", "alpha_shape"):
        return f"{len(value.triangles)} t"
    if row == "iss":
        return f"{len(value.points)} keypoints"
    if row == "detect_planar_patches":
        return f"{len(value)} patches"
    if row == "voxel_down_sample_and_trace":
        return f"{len(value[0].points)} points"
    if row == "self_intersecting_triangles":
        return f"{len(value)} pairs"
    if row in ("minimal_obb", "oriented_bounding_ellipsoid"):
        return f"volume {value.volume():.4g}"
    return ""


def run_child(library, row, threads, repeat, shared_file):
    os.environ["OMP_NUM_THREADS"] = str(threads)
    lib = __import__(library)
    if library == "o3d":
        lib.utility.set_num_threads(threads)
    else:
        lib.utility.set_verbosity_level(lib.utility.VerbosityLevel.Error)
    shared = None
    if shared_file:
        z = np.load(shared_file)
        shared = {"points": z["points"], "normals": z["normals"], "spacing": float(z["spacing"])}
    call = setup(lib, row, shared)
    # Peak first, on the warm-up call: later calls reuse heap pages the allocator kept, which would hide them.
    before = peak_kib()
    exact = reset_peak()
    before = peak_kib() if exact else before
    value = call()
    grown = peak_kib() - before
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        value = call()
        times.append(time.perf_counter() - t0)
    return {"seconds": statistics.median(times), "peak_mib": grown / 1024.0, "exact_peak": exact,
            "output": describe(row, value)}


def child(library, row, args, shared_file):
    cmd = [sys.executable, os.path.abspath(__file__), "--library", library, "--row", row, "--threads",
           str(args.threads), "--repeat", str(args.repeat)]
    if shared_file:
        cmd += ["--shared", shared_file]
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        return {"error": (out.stderr.strip().splitlines() or ["failed"])[-1]}
    return json.loads(out.stdout.strip().splitlines()[-1])


def bench(args):
    import tempfile
    import o3d
    knot = knot_samples(o3d)
    spacing = float(np.mean(np.asarray(knot.compute_nearest_neighbor_distance())))
    pool = ROWS + GEOMETRY_ROWS if args.geometry or args.only else ROWS
    rows = [r for r in pool if (not args.only or any(s in r for s in args.only)) and (not args.geometry or r in
                                                                                      GEOMETRY_ROWS)]
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        shared = os.path.join(tmp, "knot.npz")
        np.savez(shared, points=np.asarray(knot.points), normals=np.asarray(knot.normals), spacing=spacing)
        for row in rows:
            uses_knot = row in ("ball_pivoting", "alpha_shape")
            results[row] = {lib: child(lib, row, args, shared if uses_knot else None) for lib in ("o3d", "open3d")}
            print(row, json.dumps(results[row]), flush=True)
    versions = {w: subprocess.run([sys.executable, "-c", f"import {w}; print({w}.__version__)"], capture_output=True,
                                  text=True).stdout.strip() for w in ("o3d", "open3d")}
    names = {"poisson_depth8": "create_from_point_cloud_poisson(depth=8), fragment.pcd",
             "poisson_depth10": "create_from_point_cloud_poisson(depth=10), fragment.pcd",
             "ball_pivoting": f"create_from_point_cloud_ball_pivoting, knot 50k, radii {1.5 * spacing:.3g}, "
                              f"{3 * spacing:.3g}",
             "alpha_shape": f"create_from_point_cloud_alpha_shape, knot 50k, alpha {4 * spacing:.3g}",
             "orient_tangent_plane": "orient_normals_consistent_tangent_plane(10), fragment.pcd",
             "iss": "keypoint.compute_iss_keypoints (default radii), fragment.pcd",
             "smooth_mls": "smooth_mls(Hybrid(0.05, 30)), fragment.pcd",
             "smooth_laplacian": "smooth_laplacian(10, 0.5, knn 20), fragment.pcd",
             "smooth_taubin": "smooth_taubin(10, 0.5, -0.53, knn 20), fragment.pcd",
             "smooth_bilateral": "smooth_bilateral(Hybrid(0.05, 30), 0.05, 0.05), fragment.pcd",
             "estimate_point_covariances": "PointCloud.estimate_point_covariances(KNN 30), fragment.pcd",
             "detect_planar_patches": "detect_planar_patches() (defaults), fragment.pcd",
             "minimal_obb": "get_minimal_oriented_bounding_box(), fragment.pcd",
             "oriented_bounding_ellipsoid": "get_oriented_bounding_ellipsoid(), fragment.pcd",
             "voxel_down_sample_and_trace": "voxel_down_sample_and_trace(0.02, bounds), fragment.pcd",
             "filter_sharpen": "filter_sharpen(5, 0.1), knot",
             "self_intersecting_triangles": "get_self_intersecting_triangles(), knot",
             "deform_arap": "deform_as_rigid_as_possible(caps, 10 iterations), sphere 3,122 v",
             "half_edge_mesh": "HalfEdgeTriangleMesh.create_from_triangle_mesh, sphere 12,642 v"}
    title = ("Geometry algorithms of issue 22, second half" if args.geometry else
             "Surface reconstruction and point-cloud algorithms of issue 22")
    lines = ["", f"## {title} (`bench/surface_bench.py{' --geometry' if args.geometry else ''}`)", "",
             f"- Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; machine: {platform.machine()}, "
             f"{os.cpu_count()} logical CPUs, {args.threads} threads; o3d {versions['o3d']}, open3d {versions['open3d']}",
             f"- Median of {args.repeat} runs after a warm-up, each library in its own process. Ratio = Open3D time / "
             "o3d time. Peak = growth of the peak resident set during one call.", "",
             "| row | o3d | Open3D | ratio | peak MiB o3d | peak MiB Open3D | output o3d | output Open3D |",
             "|---|---:|---:|---:|---:|---:|---|---|"]
    for row in rows:
        a, b = results[row]["o3d"], results[row]["open3d"]
        if "error" in a or "error" in b:
            lines.append(f"| {names[row]} | {a.get('error', '')} | {b.get('error', '')} | | | | | |")
            continue
        lines.append(f"| {names[row]} | {a['seconds'] * 1000:.0f} ms | {b['seconds'] * 1000:.0f} ms | "
                     f"{b['seconds'] / a['seconds']:.2f}x | {a['peak_mib']:.0f} | {b['peak_mib']:.0f} | "
                     f"{a['output']} | {b['output']} |")
    return "\n".join(lines) + "\n"


# ---- accuracy against known surfaces ----------------------------------------------------------------------------

def truth_sphere(n, rng):
    u = rng.normal(size=(n, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    return u, u.copy()


def truth_torus(n, rng, big=1.0, small=0.35):
    # Area-uniform by rejection on the tube angle (the area element grows with big + small cos v).
    out_p, out_n = [], []
    while sum(len(p) for p in out_p) < n:
        u = rng.uniform(0, 2 * np.pi, n)
        v = rng.uniform(0, 2 * np.pi, n)
        keep = rng.uniform(0, 1, n) < (big + small * np.cos(v)) / (big + small)
        u, v = u[keep], v[keep]
        nrm = np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=1)
        ctr = np.stack([big * np.cos(u), big * np.sin(u), np.zeros_like(u)], axis=1)
        out_p.append(ctr + small * nrm)
        out_n.append(nrm)
    return np.concatenate(out_p)[:n], np.concatenate(out_n)[:n]


def distance_to_truth(kind, pts):
    if kind == "sphere":
        return np.abs(np.linalg.norm(pts, axis=1) - 1.0)
    if kind == "torus":
        rho = np.hypot(pts[:, 0], pts[:, 1])
        return np.abs(np.hypot(rho - 1.0, pts[:, 2]) - 0.35)
    return None


def distance_to_mesh(open3d, mesh_arrays, points):
    """Unsigned distance from each point to the triangles (Open3D's RaycastingScene: an independent measure, the
    same for both libraries' meshes)."""
    import open3d.core as o3c
    scene = open3d.t.geometry.RaycastingScene()
    vertices, triangles = mesh_arrays
    scene.add_triangles(o3c.Tensor(np.asarray(vertices, dtype=np.float32)),
                        o3c.Tensor(np.asarray(triangles, dtype=np.uint32)))
    return scene.compute_distance(o3c.Tensor(np.asarray(points, dtype=np.float32))).numpy().astype(np.float64)


def accuracy(args):
    import o3d
    import open3d
    rng = np.random.default_rng(7)
    cases = []
    sp, sn = truth_sphere(20_000, rng)
    cases.append(("sphere", sp, sn))
    tp, tn = truth_torus(30_000, rng)
    cases.append(("torus", tp, tn))
    knot_mesh = o3d.io.read_triangle_mesh(KNOT)
    knot_mesh.compute_vertex_normals()
    knot_mesh_arrays = (np.asarray(knot_mesh.vertices), np.asarray(knot_mesh.triangles))
    knot = knot_mesh.sample_points_uniformly(number_of_points=50_000, use_triangle_normal=True)
    cases.append(("knot", np.asarray(knot.points), np.asarray(knot.normals)))
    lines = ["", "## Accuracy against the true surfaces (`bench/surface_bench.py --accuracy`)", "",
             f"- Date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; o3d {o3d.__version__}, open3d "
             f"{open3d.__version__}. Distances in units of the bounding-box diagonal (x 1e-3); recon -> truth from "
             "100k points sampled on the reconstruction (analytic for the sphere and torus, to the knot's triangles for "
             "the knot), truth -> recon from the true samples to the reconstructed triangles.", "",
             "| surface | noise | method | lib | vertices | triangles | mean r->t | p99 r->t | mean t->r | p99 t->r |",
             "|---|---|---|---|---:|---:|---:|---:|---:|---:|"]
    for name, pts, nrm in cases:
        diag = float(np.linalg.norm(pts.max(0) - pts.min(0)))
        for noise in (0.0, 0.005):
            noisy = pts + rng.normal(scale=noise * diag, size=pts.shape) if noise else pts
            spacing = None
            for libname, lib in (("o3d", o3d), ("open3d", open3d)):
                pcd = lib.geometry.PointCloud()
                pcd.points = lib.utility.Vector3dVector(noisy)
                pcd.normals = lib.utility.Vector3dVector(nrm)
                if spacing is None:
                    spacing = float(np.mean(np.asarray(pcd.compute_nearest_neighbor_distance())))
                methods = {
                    "poisson d8": lambda: lib.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=8)[0],
                    "ball pivoting": lambda: lib.geometry.TriangleMesh.create_from_point_cloud_ball_pivoting(
                        pcd, lib.utility.DoubleVector([1.5 * spacing, 3.0 * spacing])),
                    "alpha shape": lambda: lib.geometry.TriangleMesh.create_from_point_cloud_alpha_shape(
                        pcd, 4.0 * spacing),
                }
                for method, make in methods.items():
                    mesh = make()
                    if len(mesh.triangles) == 0:
                        lines.append(f"| {name} | {noise} | {method} | {libname} | {len(mesh.vertices)} | 0 | | | | |")
                        continue
                    on_recon = np.asarray(mesh.sample_points_uniformly(number_of_points=100_000).points)
                    r2t = distance_to_truth(name, on_recon)
                    if r2t is None:
                        r2t = distance_to_mesh(open3d, knot_mesh_arrays, on_recon)
                    t2r = distance_to_mesh(open3d, (np.asarray(mesh.vertices), np.asarray(mesh.triangles)), pts)
                    k = 1e3 / diag
                    lines.append(f"| {name} | {noise} | {method} | {libname} | {len(mesh.vertices)} | "
                                 f"{len(mesh.triangles)} | {k * r2t.mean():.2f} | {k * np.quantile(r2t, 0.99):.2f} | "
                                 f"{k * t2r.mean():.2f} | {k * np.quantile(t2r, 0.99):.2f} |")
                    print(lines[-1], flush=True)
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--geometry", action="store_true", help="the rows of the second half (smoothing, bounding volumes, ...)")
    ap.add_argument("--accuracy", action="store_true", help="the accuracy table instead of the timings")
    ap.add_argument("--out", default=None, help="append the Markdown table to this file")
    ap.add_argument("--library", help=argparse.SUPPRESS)  # a child process
    ap.add_argument("--row", help=argparse.SUPPRESS)
    ap.add_argument("--shared", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.library:
        print(json.dumps(run_child(args.library, args.row, args.threads, args.repeat, args.shared)))
        return
    text = accuracy(args) if args.accuracy else bench(args)
    print(text)
    if args.out:
        with open(args.out, "a") as f:
            f.write(text)


if __name__ == "__main__":
    main()
