"""Long calls release the GIL: another Python thread keeps running while they work."""
import threading
import time

import numpy as np

import o3d


def max_stall_during(work):
    """Run work() in a thread; return (longest gap between main-thread ticks, work duration)."""
    done = threading.Event()
    span = {}

    def run():
        t0 = time.perf_counter()
        work()
        span["d"] = time.perf_counter() - t0
        done.set()

    t = threading.Thread(target=run)
    last = time.perf_counter()
    worst = 0.0
    t.start()
    while not done.is_set():
        now = time.perf_counter()
        worst = max(worst, now - last)
        last = now
    t.join()
    return worst, span["d"]


def test_estimate_normals_releases_gil():
    rng = np.random.default_rng(0)
    pcd = o3d.geometry.PointCloud(rng.uniform(size=(200_000, 3)))
    param = o3d.geometry.KDTreeSearchParamKNN(30)
    stall, duration = max_stall_during(lambda: pcd.estimate_normals(param))
    assert pcd.has_normals()
    assert duration > 0.05, "estimate_normals finished too fast to observe"
    # Holding the GIL would stall the main thread for the whole call.
    assert stall < 0.5 * duration


def test_batch_search_releases_gil():
    rng = np.random.default_rng(1)
    pts = rng.uniform(size=(200_000, 3))
    tree = o3d.geometry.KDTreeFlann(pts)
    result = {}
    stall, duration = max_stall_during(lambda: result.setdefault("r", tree.search_knn(pts, 20)))
    assert len(result["r"][1]) == 20 * 200_000
    assert duration > 0.05
    assert stall < 0.5 * duration
