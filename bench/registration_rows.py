"""Registration-pipeline rows of bench/bench.py (issue 5): FPFH, RANSAC, FGR, colored ICP, GICP, pose graphs.

Every row runs the same Open3D-named calls on o3d and Open3D (the vocabulary o3d mirrors), and small_gicp's own
GICP where it has one. Inputs are built in the untimed set-up; each library computes its own normals and features
there, so the timed call is the one the row names.
"""
import numpy as np

VOXEL = 0.05  # the paper's global-registration setup (Open3D tutorial): voxel 0.05, FPFH r 0.25 / 100 nn
FPFH_RADIUS, FPFH_NN = 0.25, 100
RANSAC_DIST = 1.5 * VOXEL
# A large known motion applied to cloud_bin_0 (already aligned with cloud_bin_1 to ~0.4 deg / 17 mm).
MOTION_AXIS, MOTION_DEG, MOTION_T = (0.3, -1.0, 0.5), 75.0, (0.6, -0.3, 0.4)


def _rotation(axis, degrees):
    axis = np.asarray(axis, dtype=float)
    axis /= np.linalg.norm(axis)
    a = np.radians(degrees)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K


def _motion():
    M = np.eye(4)
    M[:3, :3] = _rotation(MOTION_AXIS, MOTION_DEG)
    M[:3, 3] = MOTION_T
    return M


def _error(gt, T):
    D = np.linalg.inv(gt) @ np.asarray(T)
    ang = np.degrees(np.arccos(np.clip((np.trace(D[:3, :3]) - 1) / 2, -1, 1)))
    return f"err {ang:.2f}deg/{np.linalg.norm(D[:3, 3]) * 1000:.1f}mm"


class Rows:
    """Holds the bench context (modules, data, helpers) and appends the rows to ROWS."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.MOD = ctx["MOD"]
        self.DATA = ctx["DATA"]
        self.make_cloud = ctx["make_cloud"]
        self.threads = ctx["threads"]
        self._cache = {}

    def libs(self, names=("o3d", "open3d")):
        return [(n, self.MOD[n]) for n in names if self.MOD.get(n) is not None]

    # Inputs ------------------------------------------------------------------------------------------------------
    def down(self, mod, key, moved=False):
        """cloud_bin_{0,1} voxel-downsampled at VOXEL with hybrid(0.1, 30) normals (optionally moved)."""
        ck = (mod.__name__, key, moved)
        if ck not in self._cache:
            # The file's normals are kept so that the re-estimated ones keep their orientation (FPFH depends on it).
            pts, nrm, col = self.DATA[key]
            pc = self.make_cloud(mod, pts, nrm, col)
            if moved:
                pc.transform(_motion())
            d = pc.voxel_down_sample(VOXEL)
            d.estimate_normals(mod.geometry.KDTreeSearchParamHybrid(radius=2 * VOXEL, max_nn=30))
            self._cache[ck] = d
        return self._cache[ck]

    def fpfh(self, mod, key, moved=False):
        ck = ("fpfh", mod.__name__, key, moved)
        if ck not in self._cache:
            self._cache[ck] = mod.pipelines.registration.compute_fpfh_feature(
                self.down(mod, key, moved),
                mod.geometry.KDTreeSearchParamHybrid(radius=FPFH_RADIUS, max_nn=FPFH_NN))
        return self._cache[ck]

    def global_gt(self):
        # source = moved cloud_bin_0, target = cloud_bin_1: the answer is the inverse of the motion.
        return np.linalg.inv(_motion())

    # Rows --------------------------------------------------------------------------------------------------------
    def fpfh_impls(self):
        impls = {}
        for name, mod in self.libs():
            reg = mod.pipelines.registration
            param = mod.geometry.KDTreeSearchParamHybrid(radius=FPFH_RADIUS, max_nn=FPFH_NN)
            impls[name] = [("", lambda mod=mod: self.down(mod, "bin0"),
                            lambda pc, reg=reg, param=param: reg.compute_fpfh_feature(pc, param),
                            lambda f: f"{f.dimension()}x{f.num()}")]
        return impls

    def ransac_impls(self):
        impls = {}
        gt = self.global_gt()
        for name, mod in self.libs():
            reg = mod.pipelines.registration

            def setup(mod=mod):
                return (self.down(mod, "bin0", True), self.down(mod, "bin1"),
                        self.fpfh(mod, "bin0", True), self.fpfh(mod, "bin1"))

            def run(s, reg=reg, name=name):
                checkers = [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9),
                            reg.CorrespondenceCheckerBasedOnDistance(RANSAC_DIST)]
                kwargs = {"seed": 1} if name == "o3d" else {}
                return reg.registration_ransac_based_on_feature_matching(
                    s[0], s[1], s[2], s[3], True, RANSAC_DIST, reg.TransformationEstimationPointToPoint(False),
                    3, checkers, reg.RANSACConvergenceCriteria(100000, 0.999), **kwargs)

            impls[name] = [("", setup, run,
                            lambda r: f"fit {r.fitness:.3f} {_error(gt, r.transformation)}")]
        return impls

    def fgr_impls(self):
        impls = {}
        gt = self.global_gt()
        for name, mod in self.libs():
            reg = mod.pipelines.registration

            def setup(mod=mod):
                return (self.down(mod, "bin0", True), self.down(mod, "bin1"),
                        self.fpfh(mod, "bin0", True), self.fpfh(mod, "bin1"))

            def run(s, reg=reg):
                opt = reg.FastGlobalRegistrationOption(maximum_correspondence_distance=0.5 * VOXEL)
                return reg.registration_fgr_based_on_feature_matching(s[0], s[1], s[2], s[3], opt)

            impls[name] = [("", setup, run,
                            lambda r: f"fit {r.fitness:.3f} {_error(gt, r.transformation)}")]
        return impls

    def small_motion(self):
        M = np.eye(4)
        M[:3, :3] = _rotation([1.0, 2.0, 3.0], 4.0)
        M[:3, 3] = [0.03, -0.02, 0.015]
        return M

    def local_pair(self, mod, voxel):
        """fragment at `voxel` (target) and a copy with 2 mm noise moved by small_motion()^-1 (source)."""
        ck = ("local", mod.__name__, voxel)
        if ck not in self._cache:
            pts, nrm, col = self.DATA["fragment"]
            tgt = self.make_cloud(mod, pts, nrm, col).voxel_down_sample(voxel)
            tp = np.asarray(tgt.points)
            rng = np.random.default_rng(7)
            Ginv = np.linalg.inv(self.small_motion())
            sp = (tp + rng.normal(0.0, 0.002, size=tp.shape)) @ Ginv[:3, :3].T + Ginv[:3, 3]
            src = self.make_cloud(mod, sp, np.asarray(tgt.normals) @ Ginv[:3, :3].T, np.asarray(tgt.colors))
            self._cache[ck] = (src, tgt)
        return self._cache[ck]

    def colored_impls(self):
        impls = {}
        gt = self.small_motion()
        for name, mod in self.libs():
            reg = mod.pipelines.registration

            def run(pair, reg=reg):
                return reg.registration_colored_icp(
                    pair[0], pair[1], 0.02, np.eye(4), reg.TransformationEstimationForColoredICP(),
                    reg.ICPConvergenceCriteria(relative_fitness=1e-6, relative_rmse=1e-6, max_iteration=30))

            impls[name] = [("", lambda mod=mod: self.local_pair(mod, 0.01), run,
                            lambda r: f"fit {r.fitness:.4f} {_error(gt, r.transformation)}")]
        return impls

    def gicp_impls(self):
        impls = {}
        gt = self.small_motion()
        for name, mod in self.libs():
            reg = mod.pipelines.registration

            def run(pair, reg=reg):
                return reg.registration_generalized_icp(
                    pair[0], pair[1], 0.05, np.eye(4), reg.TransformationEstimationForGeneralizedICP(),
                    reg.ICPConvergenceCriteria(relative_fitness=1e-6, relative_rmse=1e-6, max_iteration=30))

            impls[name] = [("", lambda mod=mod: self.local_pair(mod, 0.01), run,
                            lambda r: f"fit {r.fitness:.4f} {_error(gt, r.transformation)}")]
        sg = self.MOD.get("small_gicp")
        base = self.MOD.get("open3d") or self.MOD.get("o3d")
        if sg is not None and base is not None:
            holder = {}

            def ssetup():
                # small_gicp cannot take normals: its covariances (20 nn) are estimated here, untimed, as
                # o3d/Open3D get theirs from the normals. align() on numpy arrays would voxelize at 0.25 first.
                if "pair" not in holder:
                    src, tgt = self.local_pair(base, 0.01)
                    s, t = sg.PointCloud(np.asarray(src.points)), sg.PointCloud(np.asarray(tgt.points))
                    for c in (s, t):
                        sg.estimate_covariances(c, sg.KdTree(c, num_threads=self.threads), num_neighbors=20,
                                                num_threads=self.threads)
                    holder["pair"] = (s, t)
                return holder["pair"]

            def srun(p):
                # The target tree is built inside the timed call, as o3d and Open3D build theirs.
                tree = sg.KdTree(p[1], num_threads=self.threads)
                return sg.align(p[1], p[0], tree, registration_type="GICP", max_correspondence_distance=0.05,
                                num_threads=self.threads, max_iterations=30)

            impls["small_gicp"] = [("", ssetup, srun,
                                    lambda r: f"{_error(gt, r.T_target_source)} it {r.iterations}")]
        return impls

    def pose_graph_impls(self, n=200):
        """A ring of n noisy odometry poses plus loop closures every 10 nodes (some false), LM, defaults."""
        rng = np.random.default_rng(11)
        truth = []
        for i in range(n):
            a = 2 * np.pi * i / n
            P = np.eye(4)
            P[:3, :3] = _rotation([0, 0, 1], np.degrees(a))
            P[:3, 3] = [5 * np.cos(a), 5 * np.sin(a), 0.0]
            truth.append(P)

        def noisy(T, s):
            N = np.eye(4)
            N[:3, :3] = _rotation(rng.normal(size=3), rng.normal(0, s))
            N[:3, 3] = rng.normal(0, s * 0.01, 3)
            return T @ N

        edges = []
        for i in range(n - 1):
            edges.append((i, i + 1, noisy(np.linalg.inv(truth[i + 1]) @ truth[i], 0.5), False))
        for i in range(0, n, 10):
            j = (i + n // 2) % n
            if (i // 10) % 7 == 3:  # a false loop closure
                edges.append((i, j, noisy(np.eye(4), 5.0), True))
            else:
                edges.append((i, j, noisy(np.linalg.inv(truth[j]) @ truth[i], 0.2), True))
        odo = [truth[0]]
        for s, t, T, unc in edges[:n - 1]:
            odo.append(odo[-1] @ np.linalg.inv(T))
        info = np.eye(6) * 100.0
        impls = {}
        for name, mod in self.libs():
            reg = mod.pipelines.registration

            def setup(reg=reg):
                g = reg.PoseGraph()
                for P in odo:
                    g.nodes.append(reg.PoseGraphNode(P))
                for s, t, T, unc in edges:
                    g.edges.append(reg.PoseGraphEdge(s, t, T, info, uncertain=unc))
                return g

            def run(g, reg=reg):
                reg.global_optimization(g, reg.GlobalOptimizationLevenbergMarquardt(),
                                        reg.GlobalOptimizationConvergenceCriteria(),
                                        reg.GlobalOptimizationOption(max_correspondence_distance=0.075,
                                                                     edge_prune_threshold=0.25,
                                                                     reference_node=0))
                return g

            def check(g):
                err = max(np.linalg.norm(np.asarray(g.nodes[i].pose)[:3, 3] - truth[i][:3, 3]) for i in range(n))
                return f"{len(g.edges)} edges left, max pos err {err:.3f} m"

            impls[name] = [("", setup, run, check)]
        return impls

    def add(self, ROWS):
        ROWS.append(("Registration", f"compute_fpfh_feature r={FPFH_RADIUS} nn={FPFH_NN} (cloud_bin_0, voxel 0.05)",
                     self.fpfh_impls, ""))
        ROWS.append(("Registration", "RANSAC feature matching, 100000/0.999, n=3, mutual (cloud_bin 0->1, 75 deg)",
                     self.ransac_impls, ""))
        ROWS.append(("Registration", "FGR feature matching (cloud_bin 0->1, 75 deg)", self.fgr_impls, ""))
        ROWS.append(("Registration", "colored ICP 0.02 (fragment voxel 0.01, moved copy)", self.colored_impls, ""))
        ROWS.append(("Registration", "generalized ICP 0.05 (fragment voxel 0.01, moved copy)", self.gicp_impls, ""))
        ROWS.append(("Registration", "global_optimization LM (200-node ring, 20 loop closures, 3 false)",
                     self.pose_graph_impls, ""))
