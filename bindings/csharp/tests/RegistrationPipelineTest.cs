// SPDX-License-Identifier: MIT
// The registration pipeline from C#: features, KD-trees over them, the ICP variants, correspondence checkers,
// RANSAC, FGR, pose graphs and global optimization (the same scenarios as RegistrationPipelineTest.java).
using System;
using System.IO;
using System.Linq;
using O3d;

static partial class Test
{
    static readonly double[] IDENTITY = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    const int FD = Library.FEATURE_DATA;

    static double[] Mul4(double[] a, double[] b)
    {
        var c = new double[16];
        for (int r = 0; r < 4; r++)
            for (int k = 0; k < 4; k++)
                for (int j = 0; j < 4; j++) c[4 * r + j] += a[4 * r + k] * b[4 * k + j];
        return c;
    }
    // Rotation about the unit axis (x, y, z) by deg degrees, then translation (tx, ty, tz).
    static double[] Rigid(double x, double y, double z, double deg, double tx, double ty, double tz)
    {
        double a = deg * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a), v = 1 - c;
        return new[] { c + x * x * v, x * y * v - z * s, x * z * v + y * s, tx, y * x * v + z * s, c + y * y * v, y * z * v - x * s, ty,
                       z * x * v - y * s, z * y * v + x * s, c + z * z * v, tz, 0, 0, 0, 1 };
    }
    static double[] InvertRigid(double[] t)
    {
        var r = new double[16];
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) r[4 * i + j] = t[4 * j + i];
        for (int i = 0; i < 3; i++) r[4 * i + 3] = -(r[4 * i] * t[3] + r[4 * i + 1] * t[7] + r[4 * i + 2] * t[11]);
        r[15] = 1;
        return r;
    }
    static double AngleDeg(double[] t) { return Math.Acos(Math.Max(-1, Math.Min(1, (t[0] + t[5] + t[10] - 1) / 2))) * 180 / Math.PI; }
    static double RmsGap(double[] a, double[] b, double[] points)
    {
        double[] pa = ApplyTransform(a, points), pb = ApplyTransform(b, points);
        double s = 0;
        for (int i = 0; i < pa.Length; i++) s += (pa[i] - pb[i]) * (pa[i] - pb[i]);
        return Math.Sqrt(s / (points.Length / 3));
    }
    static PointCloud WithUnitNormals(PointCloud pc, double radius) { using (var p = Hybrid(radius, 30)) pc.EstimateNormals(p, 0); return pc; }
    static double[] Diagonal6(double v) { var m = new double[36]; for (int i = 0; i < 6; i++) m[7 * i] = v; return m; }
    static Feature Fpfh(PointCloud pc, double radius, int knn, long[] indices, int threads)
    {
        using (var p = Hybrid(radius, knn)) return Library.ComputeFpfhFeature(pc, p, indices, threads);
    }
    // Runs a registration: {transformation (16), fitness, inlier rmse}; disposes the result.
    static double[] RunReg(RegistrationResult r)
    {
        using (r) return r.GetTransformation().Concat(new[] { r.GetFitness(), r.GetInlierRmse() }).ToArray();
    }
    static double[] Tf(double[] result) { return result.Take(16).ToArray(); }
    static IcpOptions IcpOpts(int estimation, int maxIteration, double relative)
    {
        return new IcpOptions { Estimation = estimation, MaxIteration = maxIteration, RelativeFitness = relative, RelativeRmse = relative };
    }
    static CorrespondenceChecker Checker(int kind, double threshold) { return new CorrespondenceChecker(kind) { Threshold = threshold }; }
    static PoseGraphEdge Edge(int s, int t, double[] tr, double[] info, bool uncertain)
    {
        var e = new PoseGraphEdge { SourceNodeId = s, TargetNodeId = t, Uncertain = uncertain ? 1 : 0 };
        if (tr != null) e.SetTransformation(tr);
        if (info != null) e.SetInformation(info);
        return e;
    }
    static double[][] Nodes(PoseGraph g) { return Enumerable.Range(0, (int)g.NumNodes()).Select(i => g.GetNode(i)).ToArray(); }
    static PointCloud Read(string path) { return Library.IoReadPointCloud(path, null, null); }
    // A global registration r of the source moved by `moved` recovers moved^-1: r * moved is near the identity.
    static void CheckGlobal(double[] r, double[] moved, double[] truthPoints, string what)
    {
        var residual = Mul4(Tf(r), moved);
        double angle = AngleDeg(residual), gap = RmsGap(residual, IDENTITY, truthPoints);
        Console.WriteLine("  " + what + ": " + angle + " deg, " + gap + " m, fitness " + r[16]);
        Check(angle < 5, what + ": rotation error " + angle + " deg");
        Check(gap < 0.1, what + ": RMS gap " + gap + " m");
    }
    // A 0.05-voxel copy of a shared scan with unit normals, as in Open3D's global registration tutorial.
    static PointCloud Preprocessed(string rel) { using (var full = Read(DataFile(rel))) return WithUnitNormals(full.VoxelDownSample(0.05), 0.1); }
    static void Invalid(Action a, string what) { ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, a, what); }

    static void RegistrationPipelineTests()
    {
        Run("Feature: create, data, view, resize, select, clone", () =>
        {
            var values = Enumerable.Range(0, 12).Select(i => (double)i).ToArray(); // 3 descriptors of 4
            using (var f = Feature.CreateFromData(values, 4, 3))
            {
                Check(f.Dimension() == 4 && f.Num() == 3, "shape");
                Check(f.GetArray(FD).SequenceEqual(values), "data");
                using (var s = f.ArrayShape(FD)) Check(s.Rows() == 3 && s.Cols() == 4, "array shape");
                Check(Copy<double>(f.ArrayView(FD), 12).SequenceEqual(values), "view");
                using (var picked = f.SelectByIndex(new long[] { 2, 0 }, 0))
                    Check(picked.GetArray(FD).SequenceEqual(new double[] { 8, 9, 10, 11, 0, 1, 2, 3 }), "select");
                using (var rest = f.SelectByIndex(new long[] { 1 }, 1))
                    Check(rest.GetArray(FD).SequenceEqual(new double[] { 0, 1, 2, 3, 8, 9, 10, 11 }), "select inverted");
                var negated = values.Select(v => -v).ToArray();
                using (var copy = f.Clone())
                {
                    f.SetArray(FD, negated);
                    Check(copy.GetArray(FD).SequenceEqual(values), "copy is deep");
                    Check(f.GetArray(FD)[5] == -5, "set");
                }
                f.Resize(4, 5);
                var resized = f.GetArray(FD);
                Check(resized.Take(12).SequenceEqual(negated) && resized.Skip(12).All(v => v == 0), "resize keeps data, zero padding");
                Invalid(() => f.SetArray(FD, new double[3]), "not a multiple of the dimension");
                Invalid(() => f.SelectByIndex(new long[] { 5 }, 0), "index out of range");
            }
            using (var zeros = Feature.Create(33, 2)) Check(zeros.GetArray(FD).SequenceEqual(new double[66]), "zeros");
            using (var empty = Feature.Create(0, 0)) Check(empty.Dimension() == 0 && empty.GetArray(FD).Length == 0, "empty");
            Invalid(() => Feature.CreateFromData(new double[] { 1, double.NaN }, 2, 1), "NaN");
            Invalid(() => Feature.CreateFromData(new double[5], 2, 3), "length");
            var gone = Feature.Create(2, 2);
            gone.Dispose();
            Throws<ObjectDisposedException>(() => gone.Num(), "after Dispose");
        });

        Run("Feature: file round trip and bad files", () =>
        {
            var values = Enumerable.Range(0, 15).Select(i => Math.Sqrt(i) - 1.5).ToArray();
            string dir = TempDir();
            try
            {
                string path = Path.Combine(dir, "f.bin");
                using (var f = Feature.CreateFromData(values, 5, 3)) Library.IoWriteFeature(path, f);
                Check(new FileInfo(path).Length == 8 + 15 * 8, "int32 dimension, int32 num, then float64 values");
                using (var back = Library.IoReadFeature(path))
                    Check(back.Dimension() == 5 && back.Num() == 3 && back.GetArray(FD).SequenceEqual(values), "round trip");
                File.WriteAllBytes(path, new byte[] { 33, 0, 0, 0, 10, 0, 0, 0, 1, 2, 3 });
                ThrowsStatus(Library.ERROR_PARSE, () => Library.IoReadFeature(path), "truncated");
                ThrowsStatus(Library.ERROR_IO, () => Library.IoReadFeature(Path.Combine(dir, "missing.bin")), "missing");
                Invalid(() => Library.IoWriteFeature(path, null), "null feature");
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("KDTreeFlann over a feature and over xd points", () =>
        {
            var rnd = new Random(11);
            var pts = Enumerable.Range(0, 1000).Select(i => rnd.NextDouble()).ToArray(); // 200 points of 5 dimensions
            var queries = Enumerable.Range(0, 15).Select(i => rnd.NextDouble()).ToArray();
            Func<int, int, double> d2 = (i, q) => Enumerable.Range(0, 5).Sum(k => Math.Pow(pts[5 * i + k] - queries[5 * q + k], 2));
            using (var f = Feature.CreateFromData(pts, 5, 200))
            using (var tree = KDTreeFlann.CreateFromFeature(f))
            using (var xd = KDTreeFlann.CreateFromPointsXd(pts, 5, 200))
            using (var k3 = Knn(3))
            using (var r = tree.SearchXd(queries, 5, k3, 0))
            using (var rx = xd.SearchXd(queries, 5, k3, 0))
            {
                Check(tree.Dimension() == 5 && xd.Dimension() == 5 && tree.Size() == 200, "dimension, size");
                var idx = r.GetIndices();
                var off = r.GetOffsets();
                Check(idx.SequenceEqual(rx.GetIndices()), "feature tree == xd tree");
                for (int q = 0; q < 3; q++)
                {
                    var order = Enumerable.Range(0, 200).OrderBy(i => d2(i, q)).Take(3);
                    Check(order.SequenceEqual(idx.Skip((int)off[q]).Take((int)(off[q + 1] - off[q]))), "query " + q);
                }
                using (var rad = Param(Library.SEARCH_RADIUS, 0, 0.3))
                using (var rr = tree.SearchXd(queries, 5, rad, 0)) Check(rr.GetOffsets().Length == 4, "radius offsets");
                Invalid(() => tree.SearchXd(new double[] { 1, 2, 3 }, 5, k3, 0), "query of 3 values");
                Invalid(() => KDTreeFlann.CreateFromPointsXd(new double[7], 2, 4), "7 values for 4 x 2");
            }
            using (var pc = new PointCloud(RandomPoints(10, 1)))
            using (var t3 = KDTreeFlann.CreateFromPointcloud(pc)) Check(t3.Dimension() == 3, "cloud tree is 3-d");
        });

        Run("CorrespondencesFromFeatures finds a permutation", () =>
        {
            var rnd = new Random(5);
            int n = 50, d = 8;
            var src = Enumerable.Range(0, n * d).Select(i => rnd.NextDouble()).ToArray();
            var perm = Enumerable.Range(0, n).OrderBy(i => rnd.Next()).ToArray();
            var tgt = new double[n * d];
            for (int i = 0; i < n; i++) Array.Copy(src, d * i, tgt, d * perm[i], d); // source i is target perm[i]
            using (var fs = Feature.CreateFromData(src, d, n))
            using (var ft = Feature.CreateFromData(tgt, d, n))
            {
                foreach (int mutual in new[] { 0, 1 })
                {
                    var pairs = Library.CorrespondencesFromFeatures(fs, ft, mutual, 0.1, 0);
                    Check(pairs.Length == 2 * n, "one pair per source descriptor");
                    for (int i = 0; i < n; i++) Check(pairs[2 * i] == i && pairs[2 * i + 1] == perm[i], "pair " + i);
                }
                using (var other = Feature.Create(3, n)) Invalid(() => Library.CorrespondencesFromFeatures(fs, other, 0, 0.1, 0), "dimensions differ");
            }
        });

        Run("FPFH on cloud_bin_0 matches the stored feature's shape", () =>
        {
            using (var stored = Library.IoReadFeature(DataFile("open3d/Feature/cloud_bin_0.fpfh.bin")))
            using (var pc = Read(DataFile("open3d/Feature/cloud_bin_0.pcd")))
            using (var fp = Fpfh(pc, 0.25, 100, null, 0))
            {
                Check(stored.Dimension() == 33 && stored.Num() == 3903, "stored shape");
                Check(fp.Dimension() == stored.Dimension() && fp.Num() == pc.Size(), "computed shape");
                var data = fp.GetArray(FD);
                // Open3D normalises each 11-bin block of the SPFH and of the weighted neighbour sum to 100: blocks sum to 200.
                for (int i = 0; i < (int)fp.Num(); i += 97)
                    for (int b = 0; b < 3; b++) Near(data.Skip(33 * i + 11 * b).Take(11).Sum(), 200, 1e-9, "p" + i + " b" + b);
                var some = new long[] { 0, 1234, 3902 };
                using (var part = Fpfh(pc, 0.25, 100, some, 0))
                using (var picked = fp.SelectByIndex(some, 0))
                    AllNear(part.GetArray(FD), picked.GetArray(FD), 1e-12, "indices: neighbourhoods from the whole cloud");
                using (var one = Fpfh(pc, 0.25, 100, null, 1)) Check(one.GetArray(FD).SequenceEqual(data), "same on 1 thread");
            }
            using (var bare = new PointCloud(RandomPoints(50, 2))) Invalid(() => Library.ComputeFpfhFeature(bare, null, null, 0), "no normals");
        });

        Run("colored, generalized and symmetric ICP recover a small transform", () =>
        {
            var t = Rigid(0.6, 0.0, 0.8, 3, 0.02, -0.015, 0.01);
            using (var fragment = Read(DataFile("open3d/fragment.pcd")))
            using (var source = WithUnitNormals(fragment.VoxelDownSample(0.02), 0.04))
            using (var target = source.Clone())
            using (var opts = IcpOpts(Library.ESTIMATION_COLORED, 60, 1e-9))
            {
                target.Transform(t);
                Check(source.HasArray(Library.POINTCLOUD_COLORS) && target.HasArray(Library.POINTCLOUD_NORMALS), "colors and normals");
                var colored = RunReg(Library.RegisterIcp(source, target, 0.05, null, opts));
                AllNear(Tf(colored), t, 2e-3, "colored");
                opts.Estimation = Library.ESTIMATION_GENERALIZED;
                var generalized = RunReg(Library.RegisterIcp(source, target, 0.05, null, opts));
                AllNear(Tf(generalized), t, 2e-3, "generalized");
                opts.Estimation = Library.ESTIMATION_SYMMETRIC;
                var symmetric = RunReg(Library.RegisterIcp(source, target, 0.05, null, opts));
                AllNear(Tf(symmetric), t, 2e-3, "symmetric");
                Check(colored[16] > 0.99 && generalized[16] > 0.99 && symmetric[16] > 0.99, "fitness");
                opts.Estimation = Library.ESTIMATION_GENERALIZED;
                AllNear(Tf(RunReg(Library.RegisterIcp(source, target, 0.05, null, opts))), Tf(generalized), 0, "deterministic");
                using (var plain = new PointCloud(source.Points))
                using (var c = IcpOpts(Library.ESTIMATION_COLORED, 30, 1e-6))
                    Invalid(() => Library.RegisterIcp(plain, target, 0.05, null, c), "colored ICP without colors");
            }
        });

        Run("Tukey kernel keeps point-to-plane ICP on target with 30% outliers", () =>
        {
            // 30% of the source are outliers lifted 4 to 8 cm off the surface along their normals: beyond the Tukey
            // scale (3 cm) near the true transform, so they get weight 0; L2 is pulled off.
            var t = Rigid(0, 0, 1, 1, 0.02, 0.01, 0);
            using (var scan = Read(DataFile("open3d/Feature/cloud_bin_0.pcd")))
            using (var clean = WithUnitNormals(scan.VoxelDownSample(0.03), 0.06))
            using (var target = clean.Clone())
            using (var source = clean.Clone())
            using (var opts = IcpOpts(Library.ESTIMATION_POINT_TO_PLANE, 100, 1e-9))
            {
                target.Transform(t);
                double[] pts = clean.Points, nrm = clean.Normals;
                int n = (int)clean.Size(), outliers = (int)(0.3 * n / 0.7);
                var rnd = new Random(3);
                var all = new double[3 * (n + outliers)];
                Array.Copy(pts, all, pts.Length);
                for (int i = 0; i < outliers; i++)
                {
                    int j = rnd.Next(n);
                    double lift = 0.04 + 0.04 * rnd.NextDouble();
                    for (int k = 0; k < 3; k++) all[3 * (n + i) + k] = pts[3 * j + k] + lift * nrm[3 * j + k];
                }
                source.Points = all;
                source.Normals = new double[0];
                opts.RobustKernel = RobustKernel.TukeyLoss(0.03);
                var robust = Tf(RunReg(Library.RegisterIcp(source, target, 0.1, null, opts)));
                opts.RobustKernel = RobustKernel.L2Loss();
                var plainT = Tf(RunReg(Library.RegisterIcp(source, target, 0.1, null, opts)));
                double robustGap = RmsGap(robust, t, pts), plainGap = RmsGap(plainT, t, pts);
                Console.WriteLine("  Tukey: " + robustGap + " m off, L2: " + plainGap + " m off");
                Check(AngleDeg(Mul4(robust, InvertRigid(t))) < 0.05, "rotation within 0.05 deg");
                Check(robustGap < 1e-3, "Tukey within 1 mm: " + robustGap);
                Check(plainGap > 0.01, "L2 is pulled more than 1 cm off by the outliers: " + plainGap);
            }
        });

        Run("correspondence checkers", () =>
        {
            var pts = new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            var move = Rigid(0, 0, 1, 90, 5, 0, 0);
            using (var source = new PointCloud(pts))
            using (var target = new PointCloud(ApplyTransform(move, pts)))
            {
                var corres = new[] { 0, 0, 1, 1, 2, 2 };
                using (var edge = new CorrespondenceChecker(Library.CHECKER_EDGE_LENGTH))
                {
                    Near(edge.Threshold, 0.9, 0, "default from o3d_correspondence_checker_init");
                    Check(edge.Check(source, target, corres, null) == 1, "rigid motion keeps edge lengths");
                    using (var stretched = new PointCloud(new double[] { 0, 0, 0, 2, 0, 0, 0, 1, 0 }))
                        Check(edge.Check(source, stretched, corres, null) == 0, "stretched");
                }
                using (var distance = Checker(Library.CHECKER_DISTANCE, 0.01))
                {
                    Check(distance.Check(source, target, corres, null) == 0, "distance without the transform");
                    Check(distance.Check(source, target, corres, move) == 1, "distance with it");
                    source.Normals = new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1 };
                    target.Normals = new double[] { 0, 0, 1, 0, 0, 1, 1, 0, 0 };
                    using (var normal = Checker(Library.CHECKER_NORMAL, 0.5)) Check(normal.Check(source, target, corres, null) == 0, "a normal off by 90 deg");
                    target.Normals = new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1 };
                    using (var normal = new CorrespondenceChecker(Library.CHECKER_NORMAL)) Check(normal.Check(source, target, corres, null) == 1, "normals agree");
                    using (var neg = Checker(Library.CHECKER_DISTANCE, -1)) Invalid(() => neg.Check(source, target, corres, null), "negative threshold");
                    Invalid(() => distance.Check(source, target, new[] { 0, 7 }, null), "index out of range");
                    Throws<O3dException>(() => distance.Check(source, target, new[] { 0 }, null), "odd pairs");
                }
            }
        });

        Run("RANSAC and FGR recover a large rotation of cloud_bin_0 onto cloud_bin_1", () =>
        {
            using (var source = Preprocessed("open3d/Feature/cloud_bin_0.pcd"))
            using (var target = Preprocessed("open3d/Feature/cloud_bin_1.pcd"))
            using (var f0 = Fpfh(source, 0.25, 100, null, 0))
            using (var f1 = Fpfh(target, 0.25, 100, null, 0))
            using (var opts = new RansacOptions())
            using (var defaults = new RansacOptions())
            using (var fgrOpts = new FgrOptions())
            {
                // cloud_bin_0 and _1 are aligned (about 0.4 deg / 17 mm): moving the source by T makes the registration
                // T^-1. FPFH is rotation invariant, so f0 still describes the moved source.
                var truthPoints = source.Points;
                var t = Rigid(0.48, 0.6, 0.64, 70, 0.4, -0.3, 0.2);
                source.Transform(t);
                var checkers = new[] { Checker(Library.CHECKER_EDGE_LENGTH, 0.9), Checker(Library.CHECKER_DISTANCE, 0.075) };
                Check(defaults.UseSeed == 0 && defaults.RansacN == 3, "defaults: unseeded, ransac_n 3");
                opts.UseSeed = 1; opts.Seed = 42; opts.MaxIteration = 100000; opts.Confidence = 0.999; opts.MutualFilter = 1;
                var r = RunReg(Library.RegisterRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
                CheckGlobal(r, t, truthPoints, "RANSAC");
                Check(r[16] > 0.3, "fitness " + r[16]);
                // refined by point-to-plane ICP it lands within the accuracy of the two scans' own alignment
                using (var p2l = new IcpOptions { Estimation = Library.ESTIMATION_POINT_TO_PLANE })
                {
                    var refined = Tf(RunReg(Library.RegisterIcp(source, target, 0.05, Tf(r), p2l)));
                    Check(AngleDeg(Mul4(refined, t)) < 1, "refined rotation error");
                    Check(RmsGap(Mul4(refined, t), IDENTITY, truthPoints) < 0.02, "refined within 2 cm");
                }
                var again = RunReg(Library.RegisterRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
                AllNear(Tf(again), Tf(r), 0, "same seed, same result");
                opts.NumThreads = 1;
                var one = RunReg(Library.RegisterRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
                opts.NumThreads = 2;
                var two = RunReg(Library.RegisterRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts));
                AllNear(Tf(two), Tf(one), 0, "1 vs 2 threads");
                AllNear(Tf(one), Tf(r), 0, "explicit vs default thread count");

                var corres = Library.CorrespondencesFromFeatures(f0, f1, 1, 0.1, 0);
                CheckGlobal(RunReg(Library.RegisterRansacBasedOnCorrespondence(source, target, corres, 0.075, checkers, opts)), t, truthPoints, "RANSAC on correspondences");
                fgrOpts.MaximumCorrespondenceDistance = 0.025; fgrOpts.UseSeed = 1; fgrOpts.Seed = 7;
                CheckGlobal(RunReg(Library.RegisterFgrBasedOnFeatureMatching(source, target, f0, f1, fgrOpts)), t, truthPoints, "FGR");
                CheckGlobal(RunReg(Library.RegisterFgrBasedOnCorrespondence(source, target, corres, fgrOpts)), t, truthPoints, "FGR on correspondences");

                // cancel from the callbacks; a throwing callback cancels too
                int calls = 0;
                opts.SetProgress(f => { calls++; return false; });
                ThrowsStatus(Library.ERROR_CANCELLED, () => Library.RegisterRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts), "RANSAC cancel");
                Check(calls == 1, "no progress call after cancelling: " + calls);
                opts.SetProgress(f => { throw new InvalidOperationException("boom"); });
                ThrowsStatus(Library.ERROR_CANCELLED, () => Library.RegisterRansacBasedOnCorrespondence(source, target, corres, 0.075, null, opts), "throwing callback");
                opts.SetProgress(null);
                using (var cancel = new FgrOptions())
                {
                    cancel.SetProgress(f => false);
                    ThrowsStatus(Library.ERROR_CANCELLED, () => Library.RegisterFgrBasedOnFeatureMatching(source, target, f0, f1, cancel), "FGR cancel");
                }

                // bad arguments
                using (var two3 = new RansacOptions { RansacN = 2 })
                using (var half = new FgrOptions { DivisionFactor = 0.5 })
                {
                    Invalid(() => Library.RegisterRansacBasedOnCorrespondence(source, target, corres, 0.075, null, two3), "ransac_n 2");
                    Invalid(() => Library.RegisterFgrBasedOnCorrespondence(source, target, corres, half), "division factor 0.5");
                }
                Invalid(() => Library.RegisterRansacBasedOnCorrespondence(source, target, new[] { 0, 1, 2, 3, 4, 1 << 30 }, 0.075, null, null), "pair out of range");
                Invalid(() => Library.RegisterRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, new[] { Checker(Library.CHECKER_EDGE_LENGTH, 2) }, null), "edge threshold 2");
                using (var wrong = Feature.Create(33, 10)) Invalid(() => Library.RegisterFgrBasedOnFeatureMatching(source, target, wrong, f1, null), "feature count");
                Invalid(() => Library.RegisterRansacBasedOnFeatureMatching(source, target, null, f1, 0.075, null, null), "null feature");
                foreach (var c in checkers) c.Dispose();
            }
        });

        Run("global random seed makes unseeded RANSAC reproducible", () =>
        {
            var pts = RandomPoints(300, 9);
            var t = Rigid(0, 0.6, 0.8, 40, 0.1, 0.2, -0.1);
            using (var source = new PointCloud(pts))
            using (var target = new PointCloud(ApplyTransform(t, pts)))
            using (var opts = new RansacOptions { MaxIteration = 2000 })
            {
                var corres = new int[600]; // the true pair of every point, except every 10th
                for (int i = 0; i < 300; i++) { corres[2 * i] = i; corres[2 * i + 1] = i % 10 == 0 ? (i * 7 + 3) % 300 : i; }
                Library.RandomSeed(123);
                var a = RunReg(Library.RegisterRansacBasedOnCorrespondence(source, target, corres, 0.01, null, opts));
                Library.RandomSeed(123);
                var b = RunReg(Library.RegisterRansacBasedOnCorrespondence(source, target, corres, 0.01, null, opts));
                AllNear(Tf(b), Tf(a), 0, "same global seed, same result");
                AllNear(Tf(a), t, 1e-6, "exact pairs give the transform");
                Check(a[16] >= 0.9 - 1e-12, "fitness " + a[16]);
            }
        });

        Run("pose graph: nodes, edges, clone, clear, bad input", () =>
        {
            using (var g = new PoseGraph())
            {
                g.AddNode(null);
                var p1 = Rigid(0, 0, 1, 30, 1, 2, 3);
                g.AddNode(p1);
                Check(g.NumNodes() == 2, "2 nodes");
                AllNear(g.GetNode(0), IDENTITY, 0, "null pose is the identity");
                AllNear(g.GetNode(1), p1, 0, "node 1");
                var info = Diagonal6(100);
                using (var e = Edge(1, 0, p1, info, true)) { e.Confidence = 0.5; g.AddEdge(e); }
                using (var back = g.GetEdge(0))
                {
                    Check(back.SourceNodeId == 1 && back.TargetNodeId == 0 && back.Uncertain == 1 && back.Confidence == 0.5, "edge fields");
                    AllNear(back.GetTransformation(), p1, 0, "edge transformation");
                    AllNear(back.GetInformation(), info, 0, "edge information");
                }
                using (var d = new PoseGraphEdge())
                {
                    AllNear(d.GetTransformation(), IDENTITY, 0, "defaults from o3d_pose_graph_edge_init");
                    AllNear(d.GetInformation(), Diagonal6(1), 0, "default information");
                    Check(d.Uncertain == 0 && d.Confidence == 1, "default flags");
                    Invalid(() => d.SetTransformation(new double[3]), "transformation of 3");
                    g.SetEdge(0, d);
                }
                using (var e0 = g.GetEdge(0)) Check(e0.Uncertain == 0 && g.NumEdges() == 1, "set edge");
                g.SetNode(0, p1);
                AllNear(Nodes(g)[0], p1, 0, "set node");
                using (var copy = g.Clone())
                {
                    g.Clear();
                    Check(g.NumNodes() == 0 && g.NumEdges() == 0, "cleared");
                    Check(copy.NumNodes() == 2 && copy.NumEdges() == 1, "clone is deep");
                }
                Invalid(() => g.GetNode(0), "node out of range");
                Invalid(() => g.GetEdge(3), "edge out of range");
                var scaled = (double[])IDENTITY.Clone(); scaled[0] = 2;
                Invalid(() => g.AddNode(scaled), "not rigid");
                var nan = (double[])IDENTITY.Clone(); nan[3] = double.NaN;
                Invalid(() => g.AddNode(nan), "NaN");
                Invalid(() => g.AddNode(new double[15]), "15 values");
                Invalid(() => g.AddEdge(null), "null edge");
                g.AddNode(null);
                using (var bad = Edge(0, 5, null, null, false)) g.AddEdge(bad);
                Invalid(() => Library.GlobalOptimization(g, null), "edge to a missing node");
                Check(g.NumNodes() == 1 && g.NumEdges() == 1, "graph unchanged");
            }
            var gone = new PoseGraph();
            gone.Dispose();
            Throws<ObjectDisposedException>(() => gone.AddNode(null), "after Dispose");
        });

        Run("pose graph JSON round trip of test_pose_graph.json", () =>
        {
            string dir = TempDir();
            try
            {
                using (var g = Library.IoReadPoseGraph(DataFile("open3d/test_pose_graph.json")))
                {
                    Check(g.NumNodes() == 2 && g.NumEdges() == 2, "2 nodes, 2 edges");
                    // The file is column-major: row-major (0, 1) is its element 4 (poses) / 6 (information).
                    var n0 = g.GetNode(0);
                    Near(n0[1], 0.1700186162907804, 0, "node 0 (0, 1)");
                    Near(n0[4], 0.12717062898648024, 0, "node 0 (1, 0)");
                    using (var e0 = g.GetEdge(0))
                    {
                        Check(e0.SourceNodeId == 1 && e0.TargetNodeId == 0 && e0.Uncertain == 0, "edge 0 ids");
                        Near(e0.GetTransformation()[1], -0.03012176885280926, 0, "edge 0 transformation (0, 1)");
                        Near(e0.GetInformation()[1], 0.03976561784722432, 0, "edge 0 information (0, 1)");
                        Near(e0.GetInformation()[6], -0.2957548753318888, 0, "edge 0 information (1, 0)");
                    }
                    string path = Path.Combine(dir, "graph.json");
                    Library.IoWritePoseGraph(path, g);
                    using (var back = Library.IoReadPoseGraph(path))
                    {
                        Check(back.NumNodes() == 2 && back.NumEdges() == 2, "read back");
                        for (uint i = 0; i < 2; i++)
                        {
                            AllNear(back.GetNode(i), g.GetNode(i), 0, "node " + i);
                            using (var a = g.GetEdge(i))
                            using (var b = back.GetEdge(i))
                            {
                                Check(a.SourceNodeId == b.SourceNodeId && a.TargetNodeId == b.TargetNodeId && a.Uncertain == b.Uncertain &&
                                      a.Confidence == b.Confidence, "edge " + i + " fields");
                                AllNear(b.GetTransformation(), a.GetTransformation(), 0, "edge " + i + " transformation");
                                AllNear(b.GetInformation(), a.GetInformation(), 0, "edge " + i + " information");
                            }
                        }
                    }
                    // its second edge joins node 2 of a two-node graph: refused, graph unchanged (Open3D refuses it too)
                    var before = Nodes(g);
                    Invalid(() => Library.GlobalOptimization(g, null), "edge to node 2");
                    AllNear(g.GetNode(0), before[0], 0, "node 0 unchanged");
                    AllNear(g.GetNode(1), before[1], 0, "node 1 unchanged");
                    Check(g.NumEdges() == 2, "edges unchanged");
                }
                string bad = Path.Combine(dir, "bad.json");
                File.WriteAllText(bad, "{\"class_name\": \"PoseGraph\", \"nodes\": [");
                ThrowsStatus(Library.ERROR_PARSE, () => Library.IoReadPoseGraph(bad), "truncated JSON");
                ThrowsStatus(Library.ERROR_IO, () => Library.IoReadPoseGraph(Path.Combine(dir, "missing.json")), "missing file");
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("global optimization prunes a false loop closure", () =>
        {
            // Five poses 1 m apart on x. Edge (s, t, T) with T = pose_t^-1 pose_s: odometry i -> i+1, two true loop
            // closures and a false one (0 -> 4 claiming a 30 deg turn and a 2 m sideways step).
            var info = Diagonal6(1000);
            using (var g = new PoseGraph())
            using (var cancel = new GlobalOptimizationOptions())
            using (var opts = new GlobalOptimizationOptions())
            {
                for (int i = 0; i < 5; i++) g.AddNode(Rigid(0, 0, 1, 0, i, 0, 0));
                g.SetNode(2, Rigid(0, 0, 1, 2, 2.05, 0.03, 0)); // a perturbed start
                Action<PoseGraphEdge> add = e => { using (e) g.AddEdge(e); };
                for (int i = 0; i < 4; i++) add(Edge(i, i + 1, Rigid(0, 0, 1, 0, -1, 0, 0), info, false));
                add(Edge(0, 3, Rigid(0, 0, 1, 0, -3, 0, 0), info, true));
                add(Edge(1, 4, Rigid(0, 0, 1, 0, -3, 0, 0), info, true));
                add(Edge(0, 4, Rigid(0, 0, 1, 30, -1, 2, 0), info, true));
                var before = Nodes(g);
                cancel.SetProgress(f => false);
                ThrowsStatus(Library.ERROR_CANCELLED, () => Library.GlobalOptimization(g, cancel), "cancel");
                for (uint i = 0; i < 5; i++) AllNear(g.GetNode(i), before[i], 0, "cancel leaves node " + i);
                Check(g.NumEdges() == 7, "cancel leaves the edges");
                int calls = 0;
                opts.SetProgress(f => { calls++; return true; });
                Check(opts.Method == Library.GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT && opts.ReferenceNode == -1 && opts.EdgePruneThreshold == 0.25, "defaults");
                using (var summary = Library.GlobalOptimization(g, opts))
                {
                    string text = summary.Iterations + " iterations, " + summary.InitialResidual + " -> " + summary.FinalResidual;
                    Check(calls > 0, "progress called");
                    Check(summary.PrunedEdges == 1 && g.NumEdges() == 6, "one edge pruned: " + text);
                    for (uint i = 0; i < g.NumEdges(); i++)
                        using (var e = g.GetEdge(i))
                        {
                            Check(!(e.SourceNodeId == 0 && e.TargetNodeId == 4), "the false closure is gone");
                            if (e.Uncertain != 0) Check(e.Confidence > 0.9, "true closures keep their confidence");
                        }
                    Check(summary.FinalResidual < summary.InitialResidual && summary.Iterations > 0, text);
                }
                for (uint i = 0; i < 5; i++) AllNear(g.GetNode(i), Rigid(0, 0, 1, 0, i, 0, 0), 1e-4, "node " + i);
            }
        });
    }
}
