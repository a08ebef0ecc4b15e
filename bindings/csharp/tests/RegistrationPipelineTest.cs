// SPDX-License-Identifier: MIT
// Tests of the registration pipeline of the C# binding: features, KD-trees over them, robust kernels, the ICP
// variants, correspondence checkers, RANSAC, FGR, pose graphs and global optimization (the same scenarios as
// bindings/java/src/test/java/org/o3d/RegistrationPipelineTest.java). Part of Test.exe (see Test.cs).
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using O3d;

static partial class Test
{
    // ---- rigid-transform helpers (row-major 4x4) ----
    static double[] Mul4(double[] a, double[] b)
    {
        var c = new double[16];
        for (int r = 0; r < 4; r++)
            for (int k = 0; k < 4; k++)
                for (int j = 0; j < 4; j++) c[4 * r + j] += a[4 * r + k] * b[4 * k + j];
        return c;
    }

    // Rotation about the unit axis (x, y, z) by `deg` degrees, then translation (tx, ty, tz).
    static double[] Rigid(double x, double y, double z, double deg, double tx, double ty, double tz)
    {
        double a = deg * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a), v = 1 - c;
        return new double[] {
            c + x * x * v, x * y * v - z * s, x * z * v + y * s, tx,
            y * x * v + z * s, c + y * y * v, y * z * v - x * s, ty,
            z * x * v - y * s, z * y * v + x * s, c + z * z * v, tz,
            0, 0, 0, 1 };
    }

    // Rotation angle (degrees) of a rigid transform.
    static double AngleDeg(double[] t)
    {
        double cos = Math.Max(-1, Math.Min(1, (t[0] + t[5] + t[10] - 1) / 2));
        return Math.Acos(cos) * 180 / Math.PI;
    }

    // RMS distance between the points moved by `a` and by `b`.
    static double RmsGap(double[] a, double[] b, double[] points)
    {
        var pa = ApplyTransform(a, points);
        var pb = ApplyTransform(b, points);
        double s = 0;
        for (int i = 0; i < pa.Length; i++) s += (pa[i] - pb[i]) * (pa[i] - pb[i]);
        return Math.Sqrt(s / (points.Length / 3));
    }

    // The voxel averages of normals are not unit vectors: re-estimate them.
    static PointCloud WithUnitNormals(PointCloud pc, double radius)
    {
        pc.EstimateNormals(SearchParam.Hybrid(radius, 30));
        return pc;
    }

    // A global registration `r` of the source moved by `moved` recovers moved^-1: r * moved is near the identity.
    static void CheckGlobal(RegistrationResult r, double[] moved, double[] truthPoints, string what)
    {
        var residual = Mul4(r.Transformation, moved);
        double angle = AngleDeg(residual), gap = RmsGap(residual, Identity4, truthPoints);
        Console.WriteLine("  " + what + ": " + angle + " deg, " + gap + " m, fitness " + r.Fitness);
        Check(angle < 5, what + ": rotation error " + angle + " deg");
        Check(gap < 0.1, what + ": RMS gap " + gap + " m");
    }

    static readonly double[] Identity4 = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

    // A 0.05-voxel copy of a shared scan with normals re-estimated and its FPFH, as in Open3D's global
    // registration tutorial (radius 2 voxels / 30 for normals, 5 voxels / 100 for FPFH).
    static PointCloud Preprocessed(string rel, out Feature fpfh)
    {
        using (var full = IO.ReadPointCloud(DataFile(rel)))
        {
            var down = full.VoxelDownSample(0.05);
            down.EstimateNormals(SearchParam.Hybrid(0.1, 30));
            fpfh = Registration.ComputeFpfhFeature(down, SearchParam.Hybrid(0.25, 100));
            return down;
        }
    }

    static void RegistrationPipelineTests()
    {
        Run("Feature: create, data, view, resize, select, clone", () =>
        {
            var values = Enumerable.Range(0, 12).Select(i => (double)i).ToArray(); // 3 descriptors of 4
            using (var f = new Feature(values, 4, 3))
            {
                Check(f.Dimension == 4 && f.Num == 3, "shape");
                Check(f.Data.SequenceEqual(values), "data");
                var view = new double[12];
                Marshal.Copy(f.DataView(), view, 0, 12);
                Check(view.SequenceEqual(values), "view");
                using (var picked = f.SelectByIndex(new long[] { 2, 0 }))
                    Check(picked.Num == 2 && picked.Data.SequenceEqual(new double[] { 8, 9, 10, 11, 0, 1, 2, 3 }), "select 2, 0");
                using (var rest = f.SelectByIndex(new long[] { 1 }, true))
                    Check(rest.Data.SequenceEqual(new double[] { 0, 1, 2, 3, 8, 9, 10, 11 }), "select inverted");
                using (var copy = f.Clone())
                {
                    f.Data = values.Select(v => -v).ToArray();
                    Check(copy.Data.SequenceEqual(values), "clone is deep");
                    Check(f.Data[5] == -5, "data set");
                }
                f.Resize(4, 5);
                Check(f.Num == 5 && f.Data.Take(12).SequenceEqual(values.Select(v => -v)) && f.Data.Skip(12).All(v => v == 0),
                      "resize keeps values, pads zeros");
                Throws<ArgumentException>(() => f.Data = new double[3], "data of the wrong length");
                ThrowsStatus(Status.InvalidArgument, () => f.SelectByIndex(new long[] { 5 }), "index out of range");
                Throws<ArgumentOutOfRangeException>(() => f.Resize(-1, 2), "negative dimension");
            }
            using (var zeros = new Feature(33, 2))
                Check(zeros.Data.Length == 66 && zeros.Data.All(v => v == 0), "zeros");
            using (var empty = new Feature())
                Check(empty.Dimension == 0 && empty.Num == 0 && empty.Data.Length == 0, "empty");
            ThrowsStatus(Status.InvalidArgument, () => new Feature(new double[] { 1, double.NaN }, 2, 1), "NaN data");
            Throws<ArgumentException>(() => new Feature(new double[5], 2, 3), "data length vs shape");
            var gone = new Feature(2, 2);
            gone.Dispose();
            Throws<ObjectDisposedException>(() => { var n = gone.Num; }, "after Dispose");
        });

        Run("Feature: file round trip and bad files", () =>
        {
            string dir = TempDir();
            try
            {
                var values = Enumerable.Range(0, 15).Select(i => Math.Sqrt(i) - 1.5).ToArray();
                string path = Path.Combine(dir, "f.bin");
                using (var f = new Feature(values, 5, 3)) IO.WriteFeature(path, f);
                Check(new FileInfo(path).Length == 8 + 15 * 8, "int32 dimension, int32 num, then float64 values");
                using (var back = IO.ReadFeature(path))
                    Check(back.Dimension == 5 && back.Num == 3 && back.Data.SequenceEqual(values), "bitwise round trip");
                File.WriteAllBytes(path, new byte[] { 33, 0, 0, 0, 10, 0, 0, 0, 1, 2, 3 });
                ThrowsStatus(Status.Parse, () => IO.ReadFeature(path), "truncated file");
                ThrowsStatus(Status.IO, () => IO.ReadFeature(Path.Combine(dir, "missing.bin")), "missing file");
                Throws<ArgumentNullException>(() => IO.WriteFeature(path, null), "null feature");
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("KDTreeFlann over a feature and over xd points", () =>
        {
            // 200 random 5-D points; the nearest neighbours must match a brute-force search.
            var rnd = new System.Random(11);
            var pts = Enumerable.Range(0, 1000).Select(i => rnd.NextDouble()).ToArray();
            var queries = Enumerable.Range(0, 15).Select(i => rnd.NextDouble()).ToArray();
            using (var f = new Feature(pts, 5, 200))
            using (var tree = new KDTreeFlann(f))
            using (var xd = KDTreeFlann.FromPointsXd(pts, 5))
            {
                Check(tree.Dimension == 5 && xd.Dimension == 5 && tree.Size == 200, "dimension, size");
                var r = tree.SearchKnnXd(queries, 3);
                var r2 = xd.SearchKnnXd(queries, 3);
                Check(r.Indices.SequenceEqual(r2.Indices), "feature tree == xd tree");
                for (int q = 0; q < 3; q++)
                {
                    var order = Enumerable.Range(0, 200).OrderBy(i =>
                        Enumerable.Range(0, 5).Sum(k => Math.Pow(pts[5 * i + k] - queries[5 * q + k], 2))).Take(3).ToArray();
                    Check(r.IndicesOf(q).SequenceEqual(order), "knn of query " + q + " = brute force");
                }
                var radius = tree.SearchRadiusXd(queries, 0.3);
                Check(radius.NumQueries == 3, "radius queries");
                Throws<ArgumentException>(() => tree.SearchKnnXd(new double[] { 1, 2, 3 }, 1), "query of the wrong dimension");
                Throws<ArgumentException>(() => KDTreeFlann.FromPointsXd(new double[7], 2), "length vs dimension");
            }
            using (var pc = new PointCloud(RandomPoints(10, 1)))
            using (var t3 = new KDTreeFlann(pc)) Check(t3.Dimension == 3, "cloud tree is 3-D");
        });

        Run("CorrespondencesFromFeatures finds a permutation", () =>
        {
            var rnd = new System.Random(5);
            const int n = 50, d = 8;
            var src = Enumerable.Range(0, n * d).Select(i => rnd.NextDouble()).ToArray();
            var perm = Enumerable.Range(0, n).OrderBy(i => rnd.Next()).ToArray();
            var tgt = new double[n * d];
            for (int i = 0; i < n; i++) Array.Copy(src, d * i, tgt, d * perm[i], d); // source i is target perm[i]
            using (var fs = new Feature(src, d, n))
            using (var ft = new Feature(tgt, d, n))
            {
                foreach (bool mutual in new[] { false, true })
                {
                    var pairs = Registration.CorrespondencesFromFeatures(fs, ft, mutual);
                    Check(pairs.Length == 2 * n, "one pair per source descriptor");
                    for (int i = 0; i < n; i++) Check(pairs[2 * i] == i && pairs[2 * i + 1] == perm[i], "pair " + i);
                }
                using (var other = new Feature(3, n))
                    ThrowsStatus(Status.InvalidArgument, () => Registration.CorrespondencesFromFeatures(fs, other), "dimension mismatch");
            }
        });

        Run("FPFH on cloud_bin_0 matches the stored feature's shape", () =>
        {
            using (var stored = IO.ReadFeature(DataFile("open3d/Feature/cloud_bin_0.fpfh.bin")))
            using (var cloud = IO.ReadPointCloud(DataFile("open3d/Feature/cloud_bin_0.pcd")))
            using (var fpfh = Registration.ComputeFpfhFeature(cloud, SearchParam.Hybrid(0.25, 100)))
            {
                Check(stored.Dimension == 33 && stored.Num == 3903, "stored 33 x 3903");
                Check(fpfh.Dimension == stored.Dimension && fpfh.Num == cloud.Size, "ours 33 x N");
                var data = fpfh.Data;
                // Open3D's FPFH normalises each 11-bin block of a point's own SPFH and of the distance-weighted sum of
                // its neighbours' SPFHs to 100, so every block of the result sums to 200 (analytic; every point here
                // has neighbours within 0.25).
                for (int i = 0; i < fpfh.Num; i += 97)
                    for (int b = 0; b < 3; b++) Near(data.Skip(33 * i + 11 * b).Take(11).Sum(), 200, 1e-9, "block sum p" + i + " b" + b);
                var some = new long[] { 0, 1234, 3902 };
                using (var part = Registration.ComputeFpfhFeature(cloud, SearchParam.Hybrid(0.25, 100), some))
                using (var picked = fpfh.SelectByIndex(some))
                    AllNear(part.Data, picked.Data, 1e-12, "indices: neighbourhoods from the whole cloud");
                using (var one = Registration.ComputeFpfhFeature(cloud, SearchParam.Hybrid(0.25, 100), null, 1))
                    Check(one.Data.SequenceEqual(data), "same on 1 thread");
            }
            using (var bare = new PointCloud(RandomPoints(50, 2)))
                ThrowsStatus(Status.InvalidArgument, () => Registration.ComputeFpfhFeature(bare), "cloud without normals");
        });

        Run("robust kernel weights", () =>
        {
            Near(RobustKernel.L2Loss().Weight(3), 1, 0, "L2");
            Near(RobustKernel.L1Loss().Weight(-2), 0.5, 1e-15, "L1 = 1/|r|");
            Near(RobustKernel.HuberLoss(1).Weight(0.5), 1, 1e-15, "Huber inside");
            Near(RobustKernel.HuberLoss(1).Weight(4), 0.25, 1e-15, "Huber k/|r|");
            Near(RobustKernel.CauchyLoss(2).Weight(2), 0.5, 1e-15, "Cauchy 1/(1+(r/k)^2)");
            Near(RobustKernel.GMLoss(1).Weight(1), 0.25, 1e-15, "GM k/(k+r^2)^2");
            Near(RobustKernel.TukeyLoss(1).Weight(0.5), 0.5625, 1e-15, "Tukey (1-(r/k)^2)^2");
            Near(RobustKernel.TukeyLoss(1).Weight(1.5), 0, 0, "Tukey outside");
            var opts = new IcpOptions();
            Check(opts.Kernel.Kind == RobustKernelKind.L2 && opts.LambdaGeometric == 0.968 && opts.Epsilon == 1e-3, "ICP defaults");
            ThrowsStatus(Status.InvalidArgument, () => RobustKernel.HuberLoss(-1).Weight(1), "k <= 0");
            ThrowsStatus(Status.InvalidArgument, () => new RobustKernel((RobustKernelKind)42).Weight(1), "unknown kernel");
        });

        Run("colored, generalized and symmetric ICP recover a small transform", () =>
        {
            var T = Rigid(0.6, 0.0, 0.8, 3, 0.02, -0.015, 0.01);
            var opts = new IcpOptions { MaxIteration = 60, RelativeFitness = 1e-9, RelativeRmse = 1e-9 };
            using (var fragment = IO.ReadPointCloud(DataFile("open3d/fragment.pcd")))
            using (var source = fragment.VoxelDownSample(0.02))
            {
                source.EstimateNormals(SearchParam.Hybrid(0.04, 30)); // unit normals (the voxel averages are not)
                using (var target = source.Clone())
                {
                    target.Transform(T);
                    Check(source.HasColors && target.HasNormals, "fragment has colors and normals");
                    var colored = Registration.RegistrationColoredIcp(source, target, 0.05, null, opts);
                    AllNear(colored.Transformation, T, 2e-3, "colored");
                    var generalized = Registration.RegistrationGeneralizedIcp(source, target, 0.05, null, opts);
                    AllNear(generalized.Transformation, T, 2e-3, "generalized");
                    var symmetric = Registration.RegistrationSymmetricIcp(source, target, 0.05, null, opts);
                    AllNear(symmetric.Transformation, T, 2e-3, "symmetric");
                    Check(colored.Fitness > 0.99 && generalized.Fitness > 0.99 && symmetric.Fitness > 0.99, "fitness");
                    opts.Estimation = EstimationMethod.Generalized; // the same through RegistrationIcp
                    AllNear(Registration.RegistrationIcp(source, target, 0.05, null, opts).Transformation, generalized.Transformation, 0, "RegistrationIcp(Generalized)");
                    using (var plain = new PointCloud(source.Points))
                        ThrowsStatus(Status.InvalidArgument, () => Registration.RegistrationColoredIcp(plain, target, 0.05), "colored ICP without colors");
                }
            }
        });

        Run("Tukey kernel keeps point-to-plane ICP on target with 30% outliers", () =>
        {
            // 30% of the source are outliers: points lifted 4 to 8 cm off the surface along their normals. Near the true
            // transform their point-to-plane residuals exceed the Tukey scale (3 cm), so they get weight 0; L2 is pulled off.
            var T = Rigid(0, 0, 1, 1, 0.02, 0.01, 0);
            using (var scan = IO.ReadPointCloud(DataFile("open3d/Feature/cloud_bin_0.pcd")))
            using (var clean = WithUnitNormals(scan.VoxelDownSample(0.03), 0.06))
            using (var target = clean.Clone())
            using (var source = clean.Clone())
            {
                target.Transform(T);
                var pts = clean.Points;
                var nrm = clean.Normals;
                int n = (int)clean.Size, outliers = (int)(0.3 * n / 0.7);
                var rnd = new System.Random(3);
                var all = pts.ToList();
                for (int i = 0; i < outliers; i++)
                {
                    int j = rnd.Next(n);
                    double lift = 0.04 + 0.04 * rnd.NextDouble();
                    for (int k = 0; k < 3; k++) all.Add(pts[3 * j + k] + lift * nrm[3 * j + k]);
                }
                source.Points = all.ToArray();
                var opts = new IcpOptions { Estimation = EstimationMethod.PointToPlane, MaxIteration = 100, RelativeFitness = 1e-9,
                                            RelativeRmse = 1e-9, Kernel = RobustKernel.TukeyLoss(0.03) };
                var robust = Registration.RegistrationIcp(source, target, 0.1, null, opts);
                opts.Kernel = RobustKernel.L2Loss();
                var plain = Registration.RegistrationIcp(source, target, 0.1, null, opts);
                double robustGap = RmsGap(robust.Transformation, T, pts), plainGap = RmsGap(plain.Transformation, T, pts);
                Console.WriteLine("  Tukey: " + robustGap + " m off, L2: " + plainGap + " m off");
                Check(AngleDeg(Mul4(robust.Transformation, InvertRigid(T))) < 0.05, "rotation within 0.05 deg");
                Check(robustGap < 1e-3, "Tukey within 1 mm");
                Check(plainGap > 0.01, "L2 is pulled more than 1 cm off by the outliers");
            }
        });

        Run("correspondence checkers", () =>
        {
            var pts = new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            using (var source = new PointCloud(pts))
            using (var target = new PointCloud(ApplyTransform(Rigid(0, 0, 1, 90, 5, 0, 0), pts)))
            {
                var corres = new[] { 0, 0, 1, 1, 2, 2 };
                Check(CorrespondenceChecker.EdgeLength().Threshold == 0.9, "edge-length default");
                Check(CorrespondenceChecker.EdgeLength(0.9).Check(source, target, corres), "rigid motion keeps edge lengths");
                using (var stretched = new PointCloud(new double[] { 0, 0, 0, 2, 0, 0, 0, 1, 0 }))
                    Check(!CorrespondenceChecker.EdgeLength(0.9).Check(source, stretched, corres), "edge 0-1 doubled");
                var distance = CorrespondenceChecker.Distance(0.01);
                Check(!distance.Check(source, target, corres), "not aligned");
                Check(distance.Check(source, target, corres, Rigid(0, 0, 1, 90, 5, 0, 0)), "aligned by the transform");
                source.Normals = new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1 };
                target.Normals = new double[] { 0, 0, 1, 0, 0, 1, 1, 0, 0 };
                Check(!CorrespondenceChecker.Normal(0.5).Check(source, target, corres), "a normal off by 90 deg");
                target.Normals = new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1 };
                Check(CorrespondenceChecker.Normal().Check(source, target, corres), "normals agree");
                ThrowsStatus(Status.InvalidArgument, () => CorrespondenceChecker.Distance(-1).Check(source, target, corres), "threshold <= 0");
                ThrowsStatus(Status.InvalidArgument, () => distance.Check(source, target, new[] { 0, 7 }), "index out of range");
                Throws<ArgumentException>(() => distance.Check(source, target, new[] { 0 }), "odd pair array");
            }
        });

        Run("RANSAC and FGR recover a large rotation of cloud_bin_0 onto cloud_bin_1", () =>
        {
            Feature f0, f1;
            using (var source = Preprocessed("open3d/Feature/cloud_bin_0.pcd", out f0))
            using (var target = Preprocessed("open3d/Feature/cloud_bin_1.pcd", out f1))
            using (f0)
            using (f1)
            {
                // cloud_bin_0 and cloud_bin_1 are aligned (to about 0.4 deg / 17 mm): moving the source by T makes
                // the registration T^-1. FPFH is rotation invariant, so f0 still describes the moved source.
                var truthPoints = source.Points;
                var T = Rigid(0.48, 0.6, 0.64, 70, 0.4, -0.3, 0.2);
                source.Transform(T);
                var checkers = new[] { CorrespondenceChecker.EdgeLength(0.9), CorrespondenceChecker.Distance(0.075) };
                var opts = new RansacOptions { Seed = 42, MaxIteration = 100000, Confidence = 0.999, MutualFilter = true };
                Check(new RansacOptions().Seed == null && new RansacOptions().RansacN == 3, "RANSAC defaults");
                var r = Registration.RegistrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts);
                CheckGlobal(r, T, truthPoints, "RANSAC");
                Check(r.Fitness > 0.3, "fitness " + r.Fitness);
                // refined by point-to-plane ICP, it lands within the accuracy of the two scans' own alignment
                var refined = Registration.RegistrationIcp(source, target, 0.05, r.Transformation,
                                                           new IcpOptions { Estimation = EstimationMethod.PointToPlane });
                Check(AngleDeg(Mul4(refined.Transformation, T)) < 1, "refined rotation error");
                Check(RmsGap(Mul4(refined.Transformation, T), Identity4, truthPoints) < 0.02, "refined within 2 cm");
                var again = Registration.RegistrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts);
                Check(again.Transformation.SequenceEqual(r.Transformation) && again.Fitness == r.Fitness, "same seed, same result");
                opts.NumThreads = 1;
                var one = Registration.RegistrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts);
                opts.NumThreads = 2;
                var two = Registration.RegistrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts);
                Check(one.Transformation.SequenceEqual(two.Transformation), "1 vs 2 threads");
                Check(one.Transformation.SequenceEqual(r.Transformation), "explicit vs default thread count");

                var corres = Registration.CorrespondencesFromFeatures(f0, f1, true);
                var rc = Registration.RegistrationRansacBasedOnCorrespondence(source, target, corres, 0.075, checkers, opts);
                CheckGlobal(rc, T, truthPoints, "RANSAC on correspondences");

                var fgr = Registration.RegistrationFgrBasedOnFeatureMatching(source, target, f0, f1,
                                                                             new FgrOptions { MaximumCorrespondenceDistance = 0.025, Seed = 7 });
                CheckGlobal(fgr, T, truthPoints, "FGR");
                var fc = Registration.RegistrationFgrBasedOnCorrespondence(source, target, corres,
                                                                           new FgrOptions { MaximumCorrespondenceDistance = 0.025, Seed = 7 });
                CheckGlobal(fc, T, truthPoints, "FGR on correspondences");

                // cancel from the callbacks; a throwing callback cancels too
                int calls = 0;
                opts.Progress = f => { calls++; return false; };
                ThrowsStatus(Status.Cancelled, () => Registration.RegistrationRansacBasedOnFeatureMatching(source, target, f0, f1, 0.075, checkers, opts), "RANSAC cancel");
                Check(calls == 1, "no progress call after cancelling, " + calls);
                opts.Progress = f => { throw new InvalidOperationException("boom"); };
                ThrowsStatus(Status.Cancelled, () => Registration.RegistrationRansacBasedOnCorrespondence(source, target, corres, 0.075, null, opts), "throwing callback");
                var fgrCancel = new FgrOptions { Progress = f => false };
                ThrowsStatus(Status.Cancelled, () => Registration.RegistrationFgrBasedOnFeatureMatching(source, target, f0, f1, fgrCancel), "FGR cancel");

                // bad arguments
                ThrowsStatus(Status.InvalidArgument, () => Registration.RegistrationRansacBasedOnCorrespondence(
                    source, target, corres, 0.075, null, new RansacOptions { RansacN = 2 }), "ransac_n < 3");
                ThrowsStatus(Status.InvalidArgument, () => Registration.RegistrationRansacBasedOnCorrespondence(
                    source, target, new[] { 0, 1, 2, 3, 4, 1 << 30 }, 0.075), "correspondence out of range");
                ThrowsStatus(Status.InvalidArgument, () => Registration.RegistrationRansacBasedOnFeatureMatching(
                    source, target, f0, f1, 0.075, new[] { CorrespondenceChecker.EdgeLength(2) }), "similarity > 1");
                ThrowsStatus(Status.InvalidArgument, () => Registration.RegistrationFgrBasedOnCorrespondence(
                    source, target, corres, new FgrOptions { DivisionFactor = 0.5 }), "division factor <= 1");
                using (var wrong = new Feature(33, 10))
                    ThrowsStatus(Status.InvalidArgument, () => Registration.RegistrationFgrBasedOnFeatureMatching(source, target, wrong, f1), "feature count vs cloud");
                Throws<ArgumentNullException>(() => Registration.RegistrationRansacBasedOnFeatureMatching(source, target, null, f1, 0.075), "null feature");
            }
        });

        Run("global random seed makes unseeded RANSAC reproducible", () =>
        {
            var pts = RandomPoints(300, 9, 1, 1, 1);
            var T = Rigid(0, 0.6, 0.8, 40, 0.1, 0.2, -0.1);
            using (var source = new PointCloud(pts))
            using (var target = new PointCloud(ApplyTransform(T, pts)))
            {
                // the true pair of every point, except every 10th, which is paired with a wrong point
                var corres = new List<int>();
                for (int i = 0; i < 300; i++) { corres.Add(i); corres.Add(i % 10 == 0 ? (i * 7 + 3) % 300 : i); }
                var opts = new RansacOptions { MaxIteration = 2000 };
                Utility.Random.Seed(123);
                var a = Registration.RegistrationRansacBasedOnCorrespondence(source, target, corres.ToArray(), 0.01, null, opts);
                Utility.Random.Seed(123);
                var b = Registration.RegistrationRansacBasedOnCorrespondence(source, target, corres.ToArray(), 0.01, null, opts);
                Check(a.Transformation.SequenceEqual(b.Transformation), "same global seed, same result");
                AllNear(a.Transformation, T, 1e-6, "exact pairs give the transform");
                Check(a.Fitness >= 0.9 - 1e-12, "fitness " + a.Fitness);
            }
        });

        Run("pose graph: nodes, edges, clone, clear, bad input", () =>
        {
            using (var g = new PoseGraph())
            {
                g.AddNode();
                var p1 = Rigid(0, 0, 1, 30, 1, 2, 3);
                g.AddNode(p1);
                Check(g.NodeCount == 2 && g.GetNode(0).SequenceEqual(Identity4) && g.GetNode(1).SequenceEqual(p1), "nodes");
                var info = Enumerable.Range(0, 36).Select(i => i % 7 == 0 ? 100.0 : 0.0).ToArray();
                var e = new PoseGraphEdge(1, 0, p1, info, true, 0.5);
                g.AddEdge(e);
                var back = g.GetEdge(0);
                Check(back.SourceNodeId == 1 && back.TargetNodeId == 0 && back.Uncertain && back.Confidence == 0.5, "edge fields");
                Check(back.Transformation.SequenceEqual(p1) && back.Information.SequenceEqual(info), "edge matrices");
                var d = new PoseGraphEdge();
                Check(d.Transformation.SequenceEqual(Identity4) && d.Information[7] == 1 && d.Information[1] == 0 && !d.Uncertain && d.Confidence == 1, "edge defaults");
                g.SetEdge(0, d);
                Check(!g.GetEdge(0).Uncertain && g.Edges.Length == 1, "set edge");
                g.SetNode(0, p1);
                Check(g.Nodes[0].SequenceEqual(p1), "set node");
                using (var copy = g.Clone())
                {
                    g.Clear();
                    Check(g.NodeCount == 0 && g.EdgeCount == 0, "cleared");
                    Check(copy.NodeCount == 2 && copy.EdgeCount == 1, "clone is deep");
                }
                ThrowsStatus(Status.InvalidArgument, () => g.GetNode(0), "node index out of range");
                ThrowsStatus(Status.InvalidArgument, () => g.GetEdge(3), "edge index out of range");
                var scaled = (double[])Identity4.Clone(); scaled[0] = 2;
                ThrowsStatus(Status.InvalidArgument, () => g.AddNode(scaled), "not rigid");
                var nan = (double[])Identity4.Clone(); nan[3] = double.NaN;
                ThrowsStatus(Status.InvalidArgument, () => g.AddNode(nan), "NaN pose");
                Throws<ArgumentException>(() => g.AddNode(new double[15]), "15 values");
                Throws<ArgumentNullException>(() => g.AddEdge(null), "null edge");
                g.AddNode();
                g.AddEdge(new PoseGraphEdge(0, 5));
                ThrowsStatus(Status.InvalidArgument, () => Registration.GlobalOptimization(g), "edge to a missing node");
                Check(g.NodeCount == 1 && g.EdgeCount == 1, "graph unchanged");
            }
            var gone = new PoseGraph();
            gone.Dispose();
            Throws<ObjectDisposedException>(() => gone.AddNode(), "after Dispose");
        });

        Run("pose graph JSON round trip of test_pose_graph.json", () =>
        {
            string dir = TempDir();
            try
            {
                using (var g = IO.ReadPoseGraph(DataFile("open3d/test_pose_graph.json")))
                {
                    Check(g.NodeCount == 2 && g.EdgeCount == 2, "2 nodes, 2 edges");
                    // The file is column-major: row-major (0, 1) is its element 4 (poses) / 6 (information).
                    var n0 = g.GetNode(0);
                    Near(n0[1], 0.1700186162907804, 0, "node 0 (0,1)");
                    Near(n0[4], 0.12717062898648024, 0, "node 0 (1,0)");
                    var e0 = g.GetEdge(0);
                    Check(e0.SourceNodeId == 1 && e0.TargetNodeId == 0 && !e0.Uncertain, "edge 0 ids");
                    Near(e0.Transformation[1], -0.03012176885280926, 0, "edge 0 transformation (0,1)");
                    Near(e0.Information[1], 0.03976561784722432, 0, "edge 0 information (0,1)");
                    Near(e0.Information[6], -0.2957548753318888, 0, "edge 0 information (1,0)");
                    string path = Path.Combine(dir, "graph.json");
                    IO.WritePoseGraph(path, g);
                    using (var back = IO.ReadPoseGraph(path))
                    {
                        Check(back.NodeCount == 2 && back.EdgeCount == 2, "counts");
                        for (int i = 0; i < 2; i++)
                        {
                            Check(back.GetNode(i).SequenceEqual(g.GetNode(i)), "node " + i);
                            var a = g.GetEdge(i); var b = back.GetEdge(i);
                            Check(a.SourceNodeId == b.SourceNodeId && a.TargetNodeId == b.TargetNodeId && a.Uncertain == b.Uncertain
                                  && a.Confidence == b.Confidence && a.Transformation.SequenceEqual(b.Transformation)
                                  && a.Information.SequenceEqual(b.Information), "edge " + i);
                        }
                    }
                }
                using (var g = IO.ReadPoseGraph(DataFile("open3d/test_pose_graph.json")))
                {
                    // its second edge joins node 2 of a two-node graph: refused, graph unchanged (Open3D refuses it too)
                    var before = g.Nodes;
                    ThrowsStatus(Status.InvalidArgument, () => Registration.GlobalOptimization(g), "test_pose_graph.json names a missing node");
                    Check(g.GetNode(0).SequenceEqual(before[0]) && g.GetNode(1).SequenceEqual(before[1]) && g.EdgeCount == 2, "unchanged");
                }
                string bad = Path.Combine(dir, "bad.json");
                File.WriteAllText(bad, "{\"class_name\": \"PoseGraph\", \"nodes\": [");
                ThrowsStatus(Status.Parse, () => IO.ReadPoseGraph(bad), "truncated JSON");
                ThrowsStatus(Status.IO, () => IO.ReadPoseGraph(Path.Combine(dir, "missing.json")), "missing file");
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("global optimization prunes a false loop closure", () =>
        {
            // Five poses 1 m apart on x. Edge (s, t, T) with T = pose_t^-1 pose_s. Odometry i -> i+1, two true loop
            // closures and one false one (0 -> 4 claiming a 30 deg turn and a 2 m sideways step).
            Func<int, double[]> pose = i => Rigid(0, 0, 1, 0, i, 0, 0);
            var info = Enumerable.Range(0, 36).Select(i => i % 7 == 0 ? 1000.0 : 0.0).ToArray();
            using (var g = new PoseGraph())
            {
                for (int i = 0; i < 5; i++) g.AddNode(pose(i));
                g.SetNode(2, Rigid(0, 0, 1, 2, 2.05, 0.03, 0)); // a perturbed start
                for (int i = 0; i < 4; i++) g.AddEdge(new PoseGraphEdge(i, i + 1, Rigid(0, 0, 1, 0, -1, 0, 0), info, false));
                g.AddEdge(new PoseGraphEdge(0, 3, Rigid(0, 0, 1, 0, -3, 0, 0), info, true));
                g.AddEdge(new PoseGraphEdge(1, 4, Rigid(0, 0, 1, 0, -3, 0, 0), info, true));
                g.AddEdge(new PoseGraphEdge(0, 4, Rigid(0, 0, 1, 30, -1, 2, 0), info, true));
                var before = g.Nodes;
                ThrowsStatus(Status.Cancelled, () => Registration.GlobalOptimization(g, new GlobalOptimizationOptions { Progress = f => false }), "cancel");
                for (int i = 0; i < 5; i++) Check(g.GetNode(i).SequenceEqual(before[i]), "cancel leaves node " + i);
                Check(g.EdgeCount == 7, "cancel leaves the edges");

                int calls = 0;
                var opts = new GlobalOptimizationOptions { Progress = f => { calls++; return true; } };
                Check(opts.Method == GlobalOptimizationMethod.LevenbergMarquardt && opts.ReferenceNode == -1 && opts.EdgePruneThreshold == 0.25, "defaults");
                var summary = Registration.GlobalOptimization(g, opts);
                Check(calls > 0, "progress called");
                Check(summary.PrunedEdges == 1 && g.EdgeCount == 6, "one edge pruned, " + summary.PrunedEdges);
                Check(g.Edges.All(e => !(e.SourceNodeId == 0 && e.TargetNodeId == 4)), "the false closure is gone");
                Check(g.Edges.Where(e => e.Uncertain).All(e => e.Confidence > 0.9), "true closures keep their confidence");
                Check(summary.FinalResidual < summary.InitialResidual && summary.Iterations > 0, "residual reduced");
                for (int i = 0; i < 5; i++) AllNear(g.GetNode(i), pose(i), 1e-4, "node " + i);
            }
        });
    }

    static double[] InvertRigid(double[] t)
    {
        var r = new double[16];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) r[4 * i + j] = t[4 * j + i];
        for (int i = 0; i < 3; i++) r[4 * i + 3] = -(r[4 * i] * t[3] + r[4 * i + 1] * t[7] + r[4 * i + 2] * t[11]);
        r[15] = 1;
        return r;
    }
}
