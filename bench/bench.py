#!/usr/bin/env python3
"""o3d against its peers (Open3D, small_gicp) on the same data, thread count and process.

Usage: python bench/bench.py [--threads N] [--repeat R] [--out bench/RESULTS.md] [--only SUBSTR ...]

Each cell is the median of R timed runs after one warm-up run; per-run set-up (building the input
objects) is excluded from the timing. Ratios are peer time / o3d time (> 1: o3d is faster).
See bench/README.md for what each row measures and which peer code path is used.
"""
import argparse
import os
import sys


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--threads", type=int, default=0, help="thread count for every library (default: all cores)")
    p.add_argument("--repeat", type=int, default=5, help="timed repetitions per cell (median reported)")
    p.add_argument("--warmup", type=int, default=1, help="untimed warm-up runs per cell")
    p.add_argument("--budget", type=float, default=20.0,
                   help="stop repeating a cell once its timed runs exceed this many seconds (min 3 runs)")
    p.add_argument("--synthetic-points", type=int, default=1_000_000, help="size of the synthetic cloud")
    p.add_argument("--seed", type=int, default=20240601, help="seed of the synthetic cloud")
    p.add_argument("--data", default=None, help="test data root (default: $O3D_TEST_DATA or <repo>/../shared/data)")
    p.add_argument("--only", nargs="*", default=None, help="run only rows whose name contains one of these")
    p.add_argument("--libs", default="o3d,open3d,small_gicp", help="comma-separated libraries to run")
    p.add_argument("--out", default=None, help="write the Markdown report here (e.g. bench/RESULTS.md)")
    p.add_argument("--note", default="", help="free text put at the top of the report (e.g. 'PRELIMINARY')")
    p.add_argument("--keep-temp", action="store_true", help="keep the temporary directory of generated files")
    args = p.parse_args(argv)
    if args.threads <= 0:
        args.threads = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return args


ARGS = parse_args()
# Open3D (and any other OpenMP user) reads OMP_NUM_THREADS when its runtime starts: set it before importing.
os.environ["OMP_NUM_THREADS"] = str(ARGS.threads)

import platform  # noqa: E402
import shutil  # noqa: E402
import statistics  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
import traceback  # noqa: E402
from importlib import metadata  # noqa: E402

import numpy as np  # noqa: E402

LIBS = ["o3d", "open3d", "small_gicp"]
PEERS = ["open3d", "small_gicp"]
WANTED = set(ARGS.libs.split(","))
MOD = {}
IMPORT_ERR = {}


def _import(name):
    if name not in WANTED:
        IMPORT_ERR[name] = "not requested"
        return None
    try:
        return __import__(name)
    except Exception as e:  # noqa: BLE001 - any import failure means: no column for this library
        IMPORT_ERR[name] = f"{type(e).__name__}: {e}"
        return None


# o3d first: it must be *our* package, not Open3D's conventional alias.
for _n in LIBS:
    MOD[_n] = _import(_n)
O3D, OPEN3D, SGICP = MOD["o3d"], MOD["open3d"], MOD["small_gicp"]

T = ARGS.threads
if O3D is not None:
    try:
        O3D.utility.set_num_threads(T)
    except Exception as e:  # noqa: BLE001
        print(f"[o3d] set_num_threads failed: {e}", file=sys.stderr)
if OPEN3D is not None:
    OPEN3D.utility.set_verbosity_level(OPEN3D.utility.VerbosityLevel.Error)
    if hasattr(OPEN3D.utility, "set_max_threads"):
        try:
            OPEN3D.utility.set_max_threads(T)
        except Exception as e:  # noqa: BLE001
            print(f"[open3d] set_max_threads failed: {e}", file=sys.stderr)


# ----------------------------------------------------------------------------------------------------------------
# Timing
# ----------------------------------------------------------------------------------------------------------------
class Skip(Exception):
    """The library lacks this operation: the cell prints '-'."""


def short_error(e):
    msg = str(e).strip().splitlines()[0] if str(e).strip() else ""
    s = f"{type(e).__name__}: {msg}" if msg else type(e).__name__
    return s if len(s) <= 90 else s[:87] + "..."


def measure(setup, run, check=None):
    """Warm-up + timed runs of run(setup()); returns (median seconds, number of runs, check(last result))."""
    times = []
    result = None
    total = ARGS.warmup + ARGS.repeat
    for i in range(total):
        state = setup() if setup is not None else None
        t0 = time.perf_counter()
        result = run(state)
        dt = time.perf_counter() - t0
        if i >= ARGS.warmup:
            times.append(dt)
            if len(times) >= 3 and sum(times) > ARGS.budget:
                break
        elif dt * 3 > ARGS.budget * 2:
            # A very slow warm-up: count it as a timed run instead of burning the budget on it.
            times.append(dt)
        del state
    info = check(result) if check is not None else ""
    return statistics.median(times), len(times), info


class Cell:
    def __init__(self, seconds=None, runs=0, info="", variant="", error=None, skipped=False):
        self.seconds, self.runs, self.info, self.variant, self.error, self.skipped = (
            seconds, runs, info, variant, error, skipped)


ROWS = []  # (group, name, {lib: [(variant, setup, run, check)]}, note)


def row(group, name, note=""):
    def deco(fn):
        ROWS.append((group, name, fn, note))
        return fn
    return deco


def run_row(impls):
    """impls: {lib: [(variant, setup, run, check)]}; the fastest variant of each library is kept."""
    cells = {}
    for lib in LIBS:
        variants = impls.get(lib)
        if MOD.get(lib) is None or not variants:
            cells[lib] = Cell(skipped=True)
            continue
        best = None
        errors = []
        for variant, setup, run, check in variants:
            try:
                sec, runs, info = measure(setup, run, check)
            except Skip:
                continue
            except Exception as e:  # noqa: BLE001 - a failing row must not stop the benchmark
                errors.append(short_error(e))
                if os.environ.get("O3D_BENCH_TRACEBACK"):
                    traceback.print_exc()
                continue
            if best is None or sec < best.seconds:
                best = Cell(sec, runs, info, variant if len(variants) > 1 else "")
        if best is None:
            cells[lib] = Cell(error="; ".join(errors)) if errors else Cell(skipped=True)
        else:
            cells[lib] = best
    return cells


# ----------------------------------------------------------------------------------------------------------------
# Data
# ----------------------------------------------------------------------------------------------------------------
def repo_root():
    return os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def data_root():
    if ARGS.data:
        return ARGS.data
    env = os.environ.get("O3D_TEST_DATA")
    if env:
        return env
    return os.path.normpath(os.path.join(repo_root(), "..", "shared", "data"))


DATA_DIR = data_root()
DATA = {}
FRAGMENT_PCD = os.path.join(DATA_DIR, "open3d", "fragment.pcd")
BIN0 = os.path.join(DATA_DIR, "open3d", "Feature", "cloud_bin_0.pcd")
BIN1 = os.path.join(DATA_DIR, "open3d", "Feature", "cloud_bin_1.pcd")
TMP = tempfile.mkdtemp(prefix="o3d-bench-")
FILES = {}       # key -> path of the shared input files (same bytes for every library)
FILE_NOTES = []  # who wrote the shared files


def synthetic_cloud(n, seed):
    """A 10 m x 10 m wavy surface with 1 cm noise: scan-like density (~1 cm spacing at 1M points)."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0.0, 10.0, size=(n, 2))
    x, y = xy[:, 0], xy[:, 1]
    z = 0.5 * np.sin(0.7 * x) * np.cos(0.5 * y) + rng.normal(0.0, 0.01, size=n)
    pts = np.column_stack([x, y, z])
    dzdx = 0.35 * np.cos(0.7 * x) * np.cos(0.5 * y)
    dzdy = -0.25 * np.sin(0.7 * x) * np.sin(0.5 * y)
    nrm = np.column_stack([-dzdx, -dzdy, np.ones(n)])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    col = rng.uniform(0.0, 1.0, size=(n, 3))
    # Colors survive a round trip through 8-bit channels exactly.
    col = np.round(col * 255.0) / 255.0
    return pts, nrm, col


def make_cloud(mod, pts, nrm=None, col=None):
    pc = mod.geometry.PointCloud()
    pc.points = mod.utility.Vector3dVector(pts)
    if nrm is not None:
        pc.normals = mod.utility.Vector3dVector(nrm)
    if col is not None:
        pc.colors = mod.utility.Vector3dVector(col)
    return pc


def arrays_of(pc):
    pts = np.asarray(pc.points).copy()
    nrm = np.asarray(pc.normals).copy() if pc.has_normals() else None
    col = np.asarray(pc.colors).copy() if pc.has_colors() else None
    return pts, nrm, col


def prepare_data():
    """Load the inputs once (with Open3D as the neutral reader if present, else o3d) and write the shared
    files once (with o3d if it can, else with Open3D). Every library then reads the same bytes."""
    reader = OPEN3D or O3D
    if reader is None:
        raise SystemExit("neither o3d nor open3d could be imported: nothing to benchmark")
    data = {}
    data["fragment"] = arrays_of(reader.io.read_point_cloud(FRAGMENT_PCD))
    data["synthetic"] = synthetic_cloud(ARGS.synthetic_points, ARGS.seed)
    data["bin0"] = arrays_of(reader.io.read_point_cloud(BIN0))
    data["bin1"] = arrays_of(reader.io.read_point_cloud(BIN1))
    FILES["fragment.pcd"] = FRAGMENT_PCD
    FILE_NOTES.append("fragment.pcd: the original file (binary PCD, float32 x y z rgb normal_xyz curvature)")
    for key, (pts, nrm, col) in (("fragment", data["fragment"]), ("synthetic", data["synthetic"])):
        for ext in ("ply", "pcd"):
            name = f"{key}.{ext}"
            if name in FILES:
                continue
            path = os.path.join(TMP, name)
            writer_used = None
            for wname, wmod in (("o3d", O3D), ("open3d", OPEN3D)):
                if wmod is None:
                    continue
                try:
                    ok = wmod.io.write_point_cloud(path, make_cloud(wmod, pts, nrm, col), write_ascii=False,
                                                   compressed=False)
                    if ok is False or not os.path.exists(path) or os.path.getsize(path) == 0:
                        raise RuntimeError("write_point_cloud returned False")
                    writer_used = wname
                    break
                except Exception as e:  # noqa: BLE001
                    print(f"[data] {wname} could not write {name}: {short_error(e)}", file=sys.stderr)
            if writer_used is None:
                raise SystemExit(f"could not write {name} with any library")
            FILES[name] = path
            FILE_NOTES.append(f"{name}: binary, written once by {writer_used} ({os.path.getsize(path) / 1e6:.1f} MB)")
    return data


# ----------------------------------------------------------------------------------------------------------------
# Rows
# ----------------------------------------------------------------------------------------------------------------
def io_rows():
    for src in ("fragment", "synthetic"):
        for ext in ("ply", "pcd"):
            key = f"{src}.{ext}"
            label = "fragment" if src == "fragment" else f"synthetic {ARGS.synthetic_points // 1000}k"

            def read_impls(path=None, key=key):
                path = FILES[key]
                impls = {}
                for lib in ("o3d", "open3d"):
                    mod = MOD[lib]
                    if mod is None:
                        continue

                    def run(_, mod=mod, path=path):
                        pc = mod.io.read_point_cloud(path)
                        if len(pc.points) == 0:
                            raise RuntimeError("read an empty cloud")
                        return pc

                    impls[lib] = [("", None, run, lambda pc: f"{len(pc.points)} pts")]
                return impls

            def write_impls(key=key, src=src, ext=ext):
                impls = {}
                for lib in ("o3d", "open3d"):
                    mod = MOD[lib]
                    if mod is None:
                        continue
                    out = os.path.join(TMP, f"out_{lib}_{src}.{ext}")
                    pts, nrm, col = DATA[src]
                    holder = {}

                    def setup(mod=mod, pts=pts, nrm=nrm, col=col, holder=holder):
                        if "pc" not in holder:
                            holder["pc"] = make_cloud(mod, pts, nrm, col)
                        return holder["pc"]

                    def run(pc, mod=mod, out=out):
                        ok = mod.io.write_point_cloud(out, pc, write_ascii=False, compressed=False)
                        if ok is False:
                            raise RuntimeError("write_point_cloud returned False")
                        return out

                    impls[lib] = [("", setup, run, lambda p: f"{os.path.getsize(p) / 1e6:.1f} MB")]
                return impls

            ROWS.append(("I/O", f"read binary {ext.upper()} ({label})", read_impls, ""))
            ROWS.append(("I/O", f"write binary {ext.upper()} ({label})", write_impls, ""))


def voxel_impls(src, voxel):
    pts, nrm, col = DATA[src]
    impls = {}
    for lib in ("o3d", "open3d"):
        mod = MOD[lib]
        if mod is None:
            continue
        holder = {}

        def setup(mod=mod, holder=holder):
            if "pc" not in holder:
                holder["pc"] = make_cloud(mod, pts, nrm, col)
            return holder["pc"]

        variants = [("", setup,
                     lambda pc: pc.voxel_down_sample(voxel), lambda r: f"{len(r.points)} pts")]
        impls[lib] = variants
    if SGICP is not None:
        impls["small_gicp"] = [("", None, lambda _: SGICP.voxelgrid_sampling(pts, voxel, T),
                                lambda r: f"{r.size()} pts (xyz only)")]
    return impls


def voxel_rows():
    for src, voxel in (("fragment", 0.01), ("fragment", 0.05), ("synthetic", 0.05)):
        label = "fragment" if src == "fragment" else f"synthetic {ARGS.synthetic_points // 1000}k"
        ROWS.append(("Downsampling", f"voxel_down_sample {voxel} ({label})",
                     lambda src=src, voxel=voxel: voxel_impls(src, voxel), ""))


def knn_impls(k=30):
    pts = DATA["synthetic"][0]
    impls = {}
    if O3D is not None:
        holder = {}

        def setup():
            if "pc" not in holder:
                holder["pc"] = make_cloud(O3D, pts)
            return holder["pc"]

        def run(pc):
            tree = O3D.geometry.KDTreeFlann(pc)
            return tree.search_knn(pts, k)

        impls["o3d"] = [("", setup, run, lambda r: f"{len(r[1])} nbrs")]
    if OPEN3D is not None:
        # Legacy KDTreeFlann only has a per-point search_knn_vector_3d: a Python loop over 1M points is not a
        # fair measure of Open3D, so its batch path (core.nns, nanoflann, multithreaded) is used.
        def run_t(_):
            t = OPEN3D.core.Tensor(pts)
            nns = OPEN3D.core.nns.NearestNeighborSearch(t)
            nns.knn_index()
            return nns.knn_search(t, k)

        impls["open3d"] = [("", None, run_t, lambda r: f"{r[0].shape[0] * r[0].shape[1]} nbrs")]
    if SGICP is not None:
        def run_s(_):
            tree = SGICP.KdTree(pts, num_threads=T)
            return tree.batch_knn_search(pts, k, num_threads=T)

        impls["small_gicp"] = [("", None, run_s, lambda r: f"{r[0].size} nbrs")]
    return impls


def normals_impls(kind):
    pts = DATA["fragment"][0]
    radius, k = 0.1, 30
    impls = {}
    for lib in ("o3d", "open3d"):
        mod = MOD[lib]
        if mod is None:
            continue
        if kind == "hybrid":
            param = lambda mod=mod: mod.geometry.KDTreeSearchParamHybrid(radius=radius, max_nn=k)  # noqa: E731
        else:
            param = lambda mod=mod: mod.geometry.KDTreeSearchParamKNN(knn=k)  # noqa: E731

        def run(pc, param=param):
            pc.estimate_normals(param())
            return pc

        # A fresh cloud without normals for every run (no orientation pass, nothing cached).
        variants = [("", lambda mod=mod: make_cloud(mod, pts), run,
                     lambda pc: f"{len(pc.normals)} normals")]
        impls[lib] = variants
    if SGICP is not None and kind == "knn":
        def ssetup():
            return SGICP.PointCloud(pts)

        def srun(pc):
            SGICP.estimate_normals(pc, num_neighbors=k, num_threads=T)
            return pc

        impls["small_gicp"] = [("", ssetup, srun, lambda pc: f"{pc.size()} normals")]
    return impls


# ICP -------------------------------------------------------------------------------------------------------------
ICP_MAX_ITER = 30


def rotation(axis, degrees):
    axis = np.asarray(axis, dtype=float)
    axis /= np.linalg.norm(axis)
    a = np.radians(degrees)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K


def icp_case(case):
    """(source arrays, target arrays, max correspondence distance, init, ground truth or None)."""
    if case == "cloud_bin":
        return DATA["bin0"], DATA["bin1"], 0.05, np.eye(4), None
    # fragment: a noisy copy moved by a known small motion, registered back onto the original.
    pts, nrm, col = DATA["fragment"]
    rng = np.random.default_rng(ARGS.seed + 1)
    G = np.eye(4)
    G[:3, :3] = rotation([1.0, 2.0, 3.0], 3.0)
    G[:3, 3] = [0.03, -0.02, 0.015]
    Ginv = np.linalg.inv(G)
    noisy = pts + rng.normal(0.0, 0.002, size=pts.shape)
    src_pts = noisy @ Ginv[:3, :3].T + Ginv[:3, 3]
    # Target = original; the true source->target transform is G.
    return (src_pts, None, None), (pts, nrm, col), 0.05, np.eye(4), G


def evaluate(src, tgt, dist, Tm):
    """Fitness / inlier RMSE of a final transform, with one common evaluator (Open3D if present, else o3d)."""
    mod = OPEN3D or O3D
    s = make_cloud(mod, src[0])
    t = make_cloud(mod, tgt[0])
    r = mod.pipelines.registration.evaluate_registration(s, t, dist, np.asarray(Tm, dtype=float))
    return r.fitness, r.inlier_rmse


def icp_info(src, tgt, dist, gt, Tm, iters=None):
    fit, rmse = evaluate(src, tgt, dist, Tm)
    s = f"fit {fit:.4f} rmse {rmse:.5f}"
    if gt is not None:
        D = np.linalg.inv(gt) @ np.asarray(Tm)
        ang = np.degrees(np.arccos(np.clip((np.trace(D[:3, :3]) - 1) / 2, -1, 1)))
        s += f" err {ang:.3f}deg/{np.linalg.norm(D[:3, 3]) * 1000:.2f}mm"
    if iters is not None:
        s += f" it {iters}"
    return s


def icp_impls(case, plane):
    src, tgt, dist, init, gt = icp_case(case)
    impls = {}
    for lib in ("o3d", "open3d"):
        mod = MOD[lib]
        if mod is None:
            continue
        reg = mod.pipelines.registration
        holder = {}

        def setup(mod=mod, holder=holder):
            if "pair" not in holder:
                holder["pair"] = (make_cloud(mod, *src), make_cloud(mod, *tgt))
            return holder["pair"]

        def run(pair, reg=reg):
            est = (reg.TransformationEstimationPointToPlane() if plane
                   else reg.TransformationEstimationPointToPoint())
            crit = reg.ICPConvergenceCriteria(max_iteration=ICP_MAX_ITER)
            return reg.registration_icp(pair[0], pair[1], dist, init, est, crit)

        impls[lib] = [("", setup, run, lambda r: icp_info(src, tgt, dist, gt, r.transformation))]
    if SGICP is not None:
        holder = {}

        def ssetup():
            if "pair" not in holder:
                s = SGICP.PointCloud(src[0])
                t = SGICP.PointCloud(tgt[0])
                if plane:
                    # small_gicp cannot take the file's normals: it estimates its own (untimed, 20 neighbours).
                    SGICP.estimate_normals(t, num_neighbors=20, num_threads=T)
                holder["pair"] = (s, t)
            return holder["pair"]

        def srun(pair):
            return SGICP.align(pair[1], pair[0], init_T_target_source=init,
                               registration_type="PLANE_ICP" if plane else "ICP",
                               max_correspondence_distance=dist, num_threads=T, max_iterations=ICP_MAX_ITER)

        impls["small_gicp"] = [("", ssetup, srun,
                                lambda r: icp_info(src, tgt, dist, gt, r.T_target_source, r.iterations))]
    return impls


def algo_rows():
    n = f"{ARGS.synthetic_points // 1000}k"
    ROWS.append(("KD-tree", f"KD-tree build + knn 30, all points (synthetic {n})", knn_impls,
                 "open3d: core.nns.NearestNeighborSearch (batch); legacy KDTreeFlann has no batch query"))
    ROWS.append(("Normals", "estimate_normals hybrid(r=0.1, 30) (fragment)", lambda: normals_impls("hybrid"), ""))
    ROWS.append(("Normals", "estimate_normals knn 30 (fragment)", lambda: normals_impls("knn"), ""))
    for case, label in (("cloud_bin", "cloud_bin_0 -> 1"), ("fragment", "fragment, moved copy")):
        ROWS.append(("ICP", f"ICP point-to-point ({label})", lambda case=case: icp_impls(case, False), ""))
        ROWS.append(("ICP", f"ICP point-to-plane ({label})", lambda case=case: icp_impls(case, True), ""))


# Geometry breadth (issue 4): meshes, point-cloud tools, RGB-D, images ---------------------------------------------
MESH_RESOLUTION = 200  # create_sphere(1, 200): 79,602 vertices, 159,200 triangles
RGBD_COLOR = os.path.join(DATA_DIR, "open3d", "RGBD", "color", "00000.jpg")
RGBD_DEPTH = os.path.join(DATA_DIR, "open3d", "RGBD", "depth", "00000.png")


def mesh_arrays():
    """A UV sphere built once (by Open3D when present, else o3d), as plain arrays every library starts from."""
    if "sphere" not in DATA:
        mod = OPEN3D or O3D
        m = mod.geometry.TriangleMesh.create_sphere(radius=1.0, resolution=MESH_RESOLUTION)
        m.compute_vertex_normals()
        DATA["sphere"] = (np.asarray(m.vertices).copy(), np.asarray(m.triangles).copy(),
                          np.asarray(m.vertex_normals).copy())
    return DATA["sphere"]


def make_mesh(mod, arrays, triangle_normals=False):
    """triangle_normals: STL stores one normal per facet (Open3D refuses to write STL without them)."""
    v, t, n = arrays
    m = mod.geometry.TriangleMesh()
    m.vertices = mod.utility.Vector3dVector(v)
    m.triangles = mod.utility.Vector3iVector(t)
    m.vertex_normals = mod.utility.Vector3dVector(n)
    if triangle_normals:
        m.compute_triangle_normals()
    return m


def mesh_file(ext):
    key = f"sphere.{ext}"
    if key not in FILES:
        path = os.path.join(TMP, key)
        for wname, wmod in (("open3d", OPEN3D), ("o3d", O3D)):
            if wmod is None:
                continue
            ok = wmod.io.write_triangle_mesh(path, make_mesh(wmod, mesh_arrays(), ext == "stl"), write_ascii=False,
                                             write_vertex_colors=False)
            if ok is not False and os.path.exists(path):
                FILES[key] = path
                FILE_NOTES.append(f"{key}: create_sphere(1, {MESH_RESOLUTION}) with vertex normals, written once "
                                  f"by {wname} ({os.path.getsize(path) / 1e6:.1f} MB)")
                break
    return FILES[key]


def per_lib(make_run, libs=("o3d", "open3d")):
    """{lib: [("", setup, run, check)]} from make_run(mod) -> (setup, run, check), for each importable lib."""
    impls = {}
    for lib in libs:
        if MOD.get(lib) is not None:
            impls[lib] = [("",) + tuple(make_run(MOD[lib]))]
    return impls


def cached(build):
    holder = {}

    def setup():
        if "v" not in holder:
            holder["v"] = build()
        return holder["v"]
    return setup


def mesh_io_impls(ext, write):
    path = mesh_file(ext)

    def make(mod):
        if write:
            out = os.path.join(TMP, f"out_{mod.__name__}_sphere.{ext}")
            return (cached(lambda: make_mesh(mod, mesh_arrays(), ext == "stl")),
                    lambda m: (mod.io.write_triangle_mesh(out, m, write_ascii=False, write_vertex_colors=False), out)[1],
                    lambda p: f"{os.path.getsize(p) / 1e6:.1f} MB")
        return (None, lambda _: mod.io.read_triangle_mesh(path),
                lambda m: f"{len(m.vertices)} v {len(m.triangles)} t")
    return per_lib(make)


def mesh_algo_impls(what):
    def make(mod):
        setup = cached(lambda: make_mesh(mod, mesh_arrays()))
        if what == "sample":
            if mod is O3D:
                return setup, lambda m: m.sample_points_uniformly(number_of_points=100_000, seed=1), \
                    lambda pc: f"{len(pc.points)} pts"
            return setup, lambda m: m.sample_points_uniformly(number_of_points=100_000), \
                lambda pc: f"{len(pc.points)} pts"
        target_triangles = len(mesh_arrays()[1]) // 10
        return setup, lambda m: m.simplify_quadric_decimation(target_number_of_triangles=target_triangles), \
            lambda r: f"{len(r.triangles)} t, area {r.get_surface_area():.5f}"
    return per_lib(make)


def cloud_tool_impls(what):
    pts, nrm, col = DATA["fragment"]

    def make(mod):
        setup = cached(lambda: make_cloud(mod, pts, nrm, col))
        if what == "statistical":
            return setup, lambda pc: pc.remove_statistical_outlier(nb_neighbors=20, std_ratio=2.0), \
                lambda r: f"{len(r[1])} kept"
        if mod is O3D:
            run = lambda pc: pc.segment_plane(distance_threshold=0.01, ransac_n=3, num_iterations=1000, seed=7)  # noqa
        else:
            run = lambda pc: pc.segment_plane(distance_threshold=0.01, ransac_n=3, num_iterations=1000)  # noqa
        return setup, run, lambda r: f"{len(r[1])} inliers"
    return per_lib(make)


def rgbd_impls():
    def make(mod):
        def setup():
            color = mod.io.read_image(RGBD_COLOR)
            depth = mod.io.read_image(RGBD_DEPTH)
            rgbd = mod.geometry.RGBDImage.create_from_color_and_depth(color, depth, convert_rgb_to_intensity=False)
            intr = mod.camera.PinholeCameraIntrinsic(mod.camera.PinholeCameraIntrinsicParameters.PrimeSenseDefault)
            return rgbd, intr
        s = cached(setup)
        return s, lambda st: mod.geometry.PointCloud.create_from_rgbd_image(st[0], st[1]), \
            lambda pc: f"{len(pc.points)} pts"
    return per_lib(make)


def image_filter_impls(kind):
    def make(mod):
        def setup():
            depth = np.asarray(mod.io.read_image(RGBD_DEPTH)).astype(np.float32) / 1000.0
            return mod.geometry.Image(depth)
        filt = getattr(mod.geometry.ImageFilterType, kind)
        return cached(setup), lambda img: img.filter(filt), lambda r: f"{np.asarray(r).shape}"
    return per_lib(make)


def geometry_rows():
    for ext in ("ply", "obj", "stl"):
        kind = "text" if ext == "obj" else "binary"
        ROWS.append(("Mesh I/O", f"read {kind} {ext.upper()} mesh (sphere 159k triangles)",
                     lambda ext=ext: mesh_io_impls(ext, False), ""))
        ROWS.append(("Mesh I/O", f"write {kind} {ext.upper()} mesh (sphere 159k triangles)",
                     lambda ext=ext: mesh_io_impls(ext, True), ""))
    ROWS.append(("Mesh", "sample_points_uniformly 100k (sphere 159k triangles)", lambda: mesh_algo_impls("sample"), ""))
    ROWS.append(("Mesh", "simplify_quadric_decimation to 10% (sphere 159k triangles)",
                 lambda: mesh_algo_impls("simplify"), ""))
    ROWS.append(("Point-cloud tools", "remove_statistical_outlier(20, 2.0) (fragment)",
                 lambda: cloud_tool_impls("statistical"), ""))
    ROWS.append(("Point-cloud tools", "segment_plane(0.01, 3, 1000) (fragment)", lambda: cloud_tool_impls("plane"), ""))
    ROWS.append(("RGB-D", "create_from_rgbd_image (640x480, PrimeSense)", rgbd_impls, ""))
    for kind in ("Gaussian7", "Sobel3dx"):
        ROWS.append(("Image", f"filter {kind} (640x480 float depth)", lambda kind=kind: image_filter_impls(kind), ""))


def registration_rows():
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from registration_rows import Rows

    Rows({"MOD": MOD, "DATA": DATA, "make_cloud": make_cloud, "threads": T}).add(ROWS)


# ----------------------------------------------------------------------------------------------------------------
# Report
# ----------------------------------------------------------------------------------------------------------------
def fmt_time(s):
    if s is None:
        return "-"
    if s < 1e-3:
        return f"{s * 1e6:.0f} us"
    if s < 1.0:
        return f"{s * 1e3:.1f} ms"
    return f"{s:.2f} s"


def fmt_cell(c):
    if c.skipped:
        return "-"
    if c.error:
        return "FAIL"
    t = fmt_time(c.seconds)
    return f"{t} ({c.variant})" if c.variant else t


def fmt_ratio(peer, ours):
    if peer.seconds is None or ours.seconds is None or ours.seconds <= 0:
        return "-"
    return f"{peer.seconds / ours.seconds:.2f}x"


def machine_info():
    model = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    logical = os.cpu_count()
    avail = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else logical
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
            mem = f", {kb / 1024 / 1024:.0f} GiB RAM"
    except (OSError, ValueError, IndexError):
        pass
    return f"{model}, {logical} logical CPUs ({avail} available to this process){mem}, {platform.platform()}"


def versions():
    def v(name, mod=None):
        if mod is not None and getattr(mod, "__version__", None):
            return str(mod.__version__)
        try:
            return metadata.version(name)
        except metadata.PackageNotFoundError:
            return "not installed"
    out = {
        "o3d": v("o3d", O3D) if O3D is not None else f"unavailable ({IMPORT_ERR.get('o3d', '')[:80]})",
        "open3d": v("open3d", OPEN3D) if OPEN3D is not None else f"unavailable ({IMPORT_ERR.get('open3d', '')})",
        "small_gicp": v("small_gicp") if SGICP is not None else f"unavailable ({IMPORT_ERR.get('small_gicp', '')})",
        "numpy": np.__version__,
        "python": platform.python_version(),
    }
    return out


def main():
    global DATA
    only = [s.lower() for s in ARGS.only] if ARGS.only else None
    print(f"threads={T}  repeat={ARGS.repeat} (median)  warmup={ARGS.warmup}  data={DATA_DIR}", flush=True)
    for k, v in versions().items():
        print(f"  {k}: {v}")
    DATA = prepare_data()
    io_rows()
    voxel_rows()
    algo_rows()
    geometry_rows()
    registration_rows()

    results = []
    header = f"{'row':<52} {'o3d':>12} {'open3d':>20} {'small_gicp':>12} {'open3d/o3d':>11} {'sgicp/o3d':>10}"
    print("\n" + header + "\n" + "-" * len(header), flush=True)
    for group, name, make, note in ROWS:
        if only and not any(s in name.lower() for s in only):
            continue
        try:
            impls = make()
        except Exception as e:  # noqa: BLE001
            print(f"{name:<52} set-up failed: {short_error(e)}", flush=True)
            continue
        cells = run_row(impls)
        results.append((group, name, cells, note))
        o = cells["o3d"]
        print(f"{name:<52} {fmt_cell(o):>12} {fmt_cell(cells['open3d']):>20} {fmt_cell(cells['small_gicp']):>12} "
              f"{fmt_ratio(cells['open3d'], o):>11} {fmt_ratio(cells['small_gicp'], o):>10}", flush=True)
        for lib in LIBS:
            c = cells[lib]
            if c.error:
                print(f"    {lib}: {c.error}", flush=True)
            elif c.info:
                print(f"    {lib}: {c.info}", flush=True)

    if ARGS.out:
        write_report(ARGS.out, results)
        print(f"\nwrote {ARGS.out}")
    if not ARGS.keep_temp:
        shutil.rmtree(TMP, ignore_errors=True)
    else:
        print(f"kept {TMP}")


def target(name, cells, misses):
    """'yes' / 'NO' / '-' for the row's targets; appends the misses with their reason."""
    o, p, g = cells["o3d"], cells["open3d"], cells["small_gicp"]
    if o.seconds is None:
        if o.error:
            misses.append(f"{name} (o3d fails)")
            return "NO"
        return "-"
    why = []
    # Issue 5 asks 2x Open3D on FPFH and RANSAC; every other row 1.5x.
    wanted = 2.0 if name.startswith(("compute_fpfh", "RANSAC")) else 1.5
    if p.seconds is not None and p.seconds / o.seconds < wanted:
        why.append(f"{p.seconds / o.seconds:.2f}x vs Open3D < {wanted}x")
    if ("point-to-plane" in name or "generalized ICP" in name) and g.seconds is not None and g.seconds / o.seconds < 1.0:
        why.append(f"{g.seconds / o.seconds:.2f}x vs small_gicp < 1x")
    if why:
        misses.append(f"{name} ({', '.join(why)})")
        return "NO"
    return "yes" if (p.seconds is not None or g.seconds is not None) else "-"


def write_report(path, results):
    vs = versions()
    lines = ["# o3d benchmark results", ""]
    if ARGS.note:
        lines += [f"**{ARGS.note}**", ""]
    lines += [
        f"- Date: {time.strftime('%Y-%m-%d %H:%M %Z')}",
        f"- Machine: {machine_info()}",
        f"- Threads: {T} for every library (o3d.utility.set_num_threads; Open3D: OMP_NUM_THREADS + "
        f"utility.set_max_threads; small_gicp: num_threads=)",
        "- Versions: " + ", ".join(f"{k} {v}" for k, v in vs.items()),
        f"- Method: median of up to {ARGS.repeat} timed runs after {ARGS.warmup} warm-up run(s) (fewer when a "
        f"cell exceeds {ARGS.budget:.0f} s, never fewer than 3), all libraries in one process, set-up excluded. "
        "Ratio = peer time / o3d time (> 1 means o3d is faster).",
        "- Inputs: " + "; ".join(FILE_NOTES),
        "",
        "## Python (`bench/bench.py`)",
        "",
        "| group | row | o3d | open3d | small_gicp | open3d / o3d | small_gicp / o3d | target met |",
        "|---|---|---:|---:|---:|---:|---:|:---:|",
    ]
    misses = []
    for group, name, cells, _ in results:
        o = cells["o3d"]
        lines.append(f"| {group} | {name} | {fmt_cell(o)} | {fmt_cell(cells['open3d'])} | "
                     f"{fmt_cell(cells['small_gicp'])} | {fmt_ratio(cells['open3d'], o)} | "
                     f"{fmt_ratio(cells['small_gicp'], o)} | {target(name, cells, misses)} |")
    lines += ["", "Targets (not asserted): o3d at least 1.5x faster than Open3D on every row; point-to-plane ICP "
              "no slower than small_gicp at the same accuracy (see the outputs table).",
              "Rows missing a target: " + ("; ".join(misses) if misses else "none") + "."]
    lines += ["", "### Outputs (to compare what each library computed) and failures", "",
              "| row | o3d | open3d | small_gicp |", "|---|---|---|---|"]
    for group, name, cells, _ in results:
        def d(c):
            if c.skipped:
                return "-"
            if c.error:
                return "FAIL: " + c.error.replace("|", "/")
            return c.info or ""
        lines.append(f"| {name} | {d(cells['o3d'])} | {d(cells['open3d'])} | {d(cells['small_gicp'])} |")
    lines += [
        "",
        "Notes on the rows:",
        "- Open3D runs its legacy (`open3d.geometry`) API, the vocabulary o3d mirrors, except the KD-tree row. "
        "Its tensor API (`open3d.t`) was tried for voxel_down_sample and estimate_normals and was 5x-40x "
        "slower on CPU (0.20), so it is not timed.",
        "- KD-tree row: build the tree over the synthetic cloud, then knn 30 for every one of its points in one "
        "batch call. Open3D's legacy KDTreeFlann has only a per-point query (a Python loop), so its batch "
        "`core.nns.NearestNeighborSearch` (knn_index + knn_search, float64) is used. small_gicp: "
        "`KdTree` + `batch_knn_search`.",
        "- small_gicp's voxelgrid_sampling averages points only (o3d/Open3D also average normals and colors); "
        "small_gicp's estimate_normals has no radius (hybrid row '-').",
        f"- ICP: same init (identity), same max correspondence distance (0.05), max_iteration {ICP_MAX_ITER}; "
        "o3d/Open3D stop on relative fitness/RMSE 1e-6, small_gicp on its own defaults (0.1 deg / 1 mm). "
        "fit/rmse are computed for every result by one common evaluator (Open3D's evaluate_registration). "
        "`fragment, moved copy`: fragment.pcd with 2 mm noise moved by a known 3 deg / 4 cm motion; "
        "`err` is the error against that ground truth. small_gicp point-to-plane uses its own target normals "
        "(estimated untimed, 20 neighbours); o3d/Open3D use the file's.",
        "- The KD-tree/normals/ICP rows include building the search tree inside the timed call for every library.",
    ]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    try:
        main()
    finally:
        if not ARGS.keep_temp:
            shutil.rmtree(TMP, ignore_errors=True)
