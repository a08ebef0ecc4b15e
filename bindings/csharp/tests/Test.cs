// SPDX-License-Identifier: MIT
// Assert-based tests of the O3d C# binding. Prints "N passed, M failed" last; exit code 1 on failure.
//   mcs -target:exe -out:Test.exe -r:O3d.dll Test.cs RegistrationPipelineTest.cs && mono Test.exe
// Data: $O3D_TEST_DATA (else $O3D_TEST_DATA_DEFAULT, else ../shared/data); tests needing it are
// skipped when it is missing, unless O3D_REQUIRE_TEST_DATA=1 (then they fail).
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using O3d;

static partial class Test
{
    static int passed, failed, skipped;

    class SkipException : Exception { public SkipException(string m) : base(m) { } }

    static void Check(bool cond, string what) { if (!cond) throw new Exception("check failed: " + what); }
    static void Near(double a, double b, double tol, string what)
    {
        if (!(Math.Abs(a - b) <= tol)) throw new Exception(string.Format("{0}: {1} vs {2} (tol {3})", what, a, b, tol));
    }
    static void AllNear(double[] a, double[] b, double tol, string what)
    {
        Check(a.Length == b.Length, what + ": length " + a.Length + " vs " + b.Length);
        for (int i = 0; i < a.Length; i++) Near(a[i], b[i], tol, what + "[" + i + "]");
    }
    static T Throws<T>(Action a, string what) where T : Exception
    {
        try { a(); }
        catch (T e) { return e; }
        catch (Exception e) { throw new Exception(what + ": expected " + typeof(T).Name + ", got " + e.GetType().Name + ": " + e.Message); }
        throw new Exception(what + ": expected " + typeof(T).Name + ", nothing thrown");
    }
    static void ThrowsStatus(Status s, Action a, string what)
    {
        var e = Throws<O3dException>(a, what);
        Check(e.Status == s, what + ": status " + e.Status + ", expected " + s);
        Check(e.Message.Length > 0, what + ": empty message");
    }

    static void Run(string name, Action body)
    {
        try { body(); passed++; Console.WriteLine("PASS " + name); }
        catch (SkipException e) { skipped++; Console.WriteLine("SKIP " + name + ": " + e.Message); }
        catch (Exception e) { failed++; Console.WriteLine("FAIL " + name + ": " + e.GetType().Name + ": " + e.Message); }
    }

    static string DataFile(string rel)
    {
        string dir = Environment.GetEnvironmentVariable("O3D_TEST_DATA");
        if (string.IsNullOrEmpty(dir)) dir = Environment.GetEnvironmentVariable("O3D_TEST_DATA_DEFAULT");
        if (string.IsNullOrEmpty(dir)) dir = Path.Combine("..", "shared", "data");
        string path = Path.Combine(dir, rel);
        if (!File.Exists(path))
        {
            if (Environment.GetEnvironmentVariable("O3D_REQUIRE_TEST_DATA") == "1")
                throw new Exception("missing test data (O3D_REQUIRE_TEST_DATA=1): " + path);
            throw new SkipException("missing test data " + path);
        }
        return path;
    }

    static string TempDir()
    {
        string d = Path.Combine(Path.GetTempPath(), "o3d_cs_" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(d);
        return d;
    }

    static double[] RandomPoints(int n, int seed, double sx = 1, double sy = 1, double sz = 1)
    {
        var r = new Random(seed);
        var p = new double[3 * n];
        for (int i = 0; i < n; i++) { p[3 * i] = r.NextDouble() * sx; p[3 * i + 1] = r.NextDouble() * sy; p[3 * i + 2] = r.NextDouble() * sz; }
        return p;
    }

    static double[] ApplyTransform(double[] T, double[] p)
    {
        var q = new double[p.Length];
        for (int i = 0; i < p.Length / 3; i++)
            for (int r = 0; r < 3; r++)
                q[3 * i + r] = T[4 * r] * p[3 * i] + T[4 * r + 1] * p[3 * i + 1] + T[4 * r + 2] * p[3 * i + 2] + T[4 * r + 3];
        return q;
    }

    // ---- fixtures of the point-cloud tools tests (the same in O3dTest.java) ----
    // A 10 x 10 grid (spacing 0.1) at z = 0, indices 0..99, then two far outliers (100, 101).
    static double[] GridWithOutliers()
    {
        var p = new List<double>();
        for (int i = 0; i < 10; i++)
            for (int j = 0; j < 10; j++) { p.Add(i * 0.1); p.Add(j * 0.1); p.Add(0); }
        p.AddRange(new double[] { 5, 5, 5, -5, -5, 5 });
        return p.ToArray();
    }
    static int[] Range(int start, int count) { return Enumerable.Range(start, count).ToArray(); }
    // Points of a 3 x 3 x 3 grid (spacing 0.1) around (cx, cy, cz).
    static IEnumerable<double> Blob(double cx, double cy, double cz)
    {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) { yield return cx + i * 0.1; yield return cy + j * 0.1; yield return cz + k * 0.1; }
    }

    static int Main()
    {
        Run("version", () =>
        {
            Check(Library.VersionMajor == 0, "major");
            Check(Library.Version == Library.VersionMajor + "." + Library.VersionMinor + "." + Library.VersionPatch, "version string");
            Check(Library.StatusString(Status.IO) == "O3D_ERROR_IO", "status string");
        });

        Run("points round trip float64 and float32", () =>
        {
            var pts = new double[] { 1, 2, 3, 4.5, -5.25, 6, 1e-3, 7, -8 };
            using (var pc = new PointCloud())
            {
                Check(pc.Size == 0 && !pc.HasPoints, "empty");
                pc.Points = pts;
                Check(pc.Size == 3 && pc.HasPoints && !pc.HasNormals && !pc.HasColors, "size 3");
                AllNear(pc.Points, pts, 0, "f64");
                pts[0] = 99; // the cloud holds a copy
                Near(pc.Points[0], 1, 0, "copy in");
                var f = new float[] { 0.5f, 1.25f, -2f, 3f, 4f, 5.5f };
                pc.SetPoints(f);
                Check(pc.Size == 2, "f32 size");
                AllNear(pc.Points, f.Select(x => (double)x).ToArray(), 0, "f32");
                pc.Normals = new double[] { 0, 0, 1, 0, 1, 0 };
                pc.SetColors(new float[] { 1, 0, 0, 0, 0.5f, 1 });
                Check(pc.HasNormals && pc.HasColors, "normals/colors");
                AllNear(pc.Colors, new double[] { 1, 0, 0, 0, 0.5, 1 }, 0, "colors");
                Throws<ArgumentException>(() => pc.Points = new double[4], "length not multiple of 3");
                long rows;
                IntPtr v = pc.PointsView(out rows);
                Check(rows == 2 && v != IntPtr.Zero, "view");
                var copy = new double[6];
                Marshal.Copy(v, copy, 0, 6);
                AllNear(copy, pc.Points, 0, "view contents");
                IntPtr mv = pc.PointsMutableView(out rows);
                Marshal.Copy(new double[] { 7, 8, 9 }, 0, mv, 3);
                AllNear(pc.Points.Take(3).ToArray(), new double[] { 7, 8, 9 }, 0, "mutable view write");
                using (var c = pc.Clone())
                {
                    pc.Clear();
                    Check(pc.Size == 0 && c.Size == 2, "clone is deep");
                }
            }
        });

        Run("voxel_down_sample averages", () =>
        {
            var pts = new double[] { 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.2, 5, 5, 5, 5.2, 5, 5 };
            using (var pc = new PointCloud(pts))
            using (var down = pc.VoxelDownSample(1.0))
            {
                Check(down.Size == 2, "2 voxels, got " + down.Size);
                var d = down.Points;
                int a = d[0] < d[3] ? 0 : 1, b = 1 - a;
                AllNear(d.Skip(3 * a).Take(3).ToArray(), new double[] { 0.1 / 3, 0.1 / 3, 0.2 / 3 }, 1e-12, "cluster A mean");
                AllNear(d.Skip(3 * b).Take(3).ToArray(), new double[] { 5.1, 5, 5 }, 1e-12, "cluster B mean");
                Check(pc.Size == 5, "input untouched");
            }
        });

        Run("normals of a sampled plane", () =>
        {
            var pts = new List<double>();
            for (int i = 0; i < 20; i++)
                for (int j = 0; j < 20; j++) { double x = i * 0.05, y = j * 0.05; pts.Add(x); pts.Add(y); pts.Add(0.3 * x + 0.2 * y); }
            double nn = Math.Sqrt(0.09 + 0.04 + 1);
            using (var pc = new PointCloud(pts.ToArray()))
            {
                pc.EstimateNormals(SearchParam.Hybrid(0.2, 16));
                Check(pc.HasNormals, "has normals");
                var n = pc.Normals;
                Check(n.Length == pts.Count, "one per point");
                for (int i = 0; i < n.Length / 3; i++)
                {
                    double dot = (-0.3 * n[3 * i] - 0.2 * n[3 * i + 1] + n[3 * i + 2]) / nn;
                    Near(Math.Abs(dot), 1, 1e-6, "normal " + i);
                }
                pc.OrientNormalsToAlignWithDirection(new double[] { 0, 0, -1 });
                Check(pc.Normals[2] < 0, "oriented to -Z");
                pc.EstimateNormals(); // default KNN 30 keeps working
            }
        });

        Run("knn vs brute force", () =>
        {
            var pts = RandomPoints(500, 1);
            var queries = RandomPoints(20, 2);
            const int k = 5;
            using (var tree = new KDTreeFlann(pts))
            {
                Check(tree.Size == 500, "tree size");
                var res = tree.SearchKnn(queries, k);
                Check(res.NumQueries == 20 && res.Indices.Length == 20 * k, "counts");
                for (int q = 0; q < 20; q++)
                {
                    var d = Enumerable.Range(0, 500).Select(i =>
                    {
                        double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                        return new { i, d2 = dx * dx + dy * dy + dz * dz };
                    }).OrderBy(x => x.d2).Take(k).ToArray();
                    Check(res.Offsets[q] == q * k, "offset");
                    for (int j = 0; j < k; j++)
                    {
                        Check(res.Indices[q * k + j] == d[j].i, "index q" + q + " j" + j);
                        Near(res.Distances2[q * k + j], d[j].d2, 1e-12, "d2");
                    }
                }
                // float32 queries and the zero-copy view give the same neighbours
                var fq = queries.Select(x => (float)x).ToArray();
                using (var pc = new PointCloud(pts))
                using (var tree2 = new KDTreeFlann(pc))
                using (var raw = tree2.Search(fq, SearchParam.Knn(1)))
                {
                    long nq, total;
                    raw.GetCounts(out nq, out total);
                    Check(nq == 20 && total == 20, "raw counts");
                    IntPtr po, pi, pd;
                    raw.GetView(out po, out pi, out pd);
                    var idx = new int[20];
                    Marshal.Copy(pi, idx, 0, 20);
                    for (int q = 0; q < 20; q++) Check(idx[q] == res.Indices[q * k], "f32 nearest q" + q);
                }
                var rad = tree.SearchRadius(queries, 0.1);
                for (int q = 0; q < 20; q++)
                {
                    int expect = Enumerable.Range(0, 500).Count(i =>
                    {
                        double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                        return dx * dx + dy * dy + dz * dz <= 0.01;
                    });
                    Check(rad.Offsets[q + 1] - rad.Offsets[q] == expect, "radius count q" + q);
                }
            }
        });

        Run("ICP recovers a known transform", () =>
        {
            var src = RandomPoints(800, 3, 1.0, 2.0, 0.5);
            double a = 5 * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
            var T = new double[] { c, -s, 0, 0.05, s, c, 0, -0.03, 0, 0, 1, 0.02, 0, 0, 0, 1 };
            using (var source = new PointCloud(src))
            using (var target = new PointCloud(ApplyTransform(T, src)))
            {
                int calls = 0;
                var opts = new IcpOptions { MaxIteration = 100, RelativeFitness = 1e-10, RelativeRmse = 1e-10, Progress = f => { calls++; return true; } };
                Check(opts.Estimation == EstimationMethod.PointToPoint && !opts.WithScaling, "defaults");
                var r = Registration.RegistrationIcp(source, target, 0.3, null, opts);
                AllNear(r.Transformation, T, 1e-4, "transformation");
                Near(r.Fitness, 1, 1e-9, "fitness");
                Check(r.InlierRmse < 1e-4, "rmse " + r.InlierRmse);
                Check(r.CorrespondenceSet.Length == 2 * 800, "correspondences");
                Check(calls > 0, "progress called");
                var e = Registration.EvaluateRegistration(source, target, 0.01, T);
                Near(e.Fitness, 1, 1e-12, "evaluate fitness");
                var info = Registration.GetInformationMatrixFromPointClouds(source, target, 0.01, T);
                Check(info.Length == 36 && info[0] > 0, "information matrix");
                opts.Progress = f => false;
                ThrowsStatus(Status.Cancelled, () => Registration.RegistrationIcp(source, target, 0.3, null, opts), "cancel");
            }
        });

        Run("read/write file and memory round trip", () =>
        {
            var pts = RandomPoints(100, 4);
            var nrm = Enumerable.Range(0, 100).SelectMany(i => new double[] { 0, 0, 1 }).ToArray();
            string dir = TempDir();
            try
            {
                using (var pc = new PointCloud(pts))
                {
                    pc.Normals = nrm;
                    pc.PaintUniformColor(new double[] { 1, 0.5, 0 });
                    foreach (var fmt in new[] { "ply", "pcd", "xyz" })
                    {
                        string path = Path.Combine(dir, "c." + fmt);
                        IO.WritePointCloud(path, pc);
                        Check(File.Exists(path), fmt + " written");
                        using (var back = IO.ReadPointCloud(path))
                        {
                            Check(back.Size == 100, fmt + " size");
                            AllNear(back.Points, pts, 1e-5, fmt + " points");
                        }
                    }
                    using (var back = IO.ReadPointCloud(Path.Combine(dir, "c.ply")))
                    {
                        Check(back.HasNormals && back.HasColors, "ply keeps normals+colors");
                        AllNear(back.Normals, nrm, 1e-6, "ply normals");
                    }
                    foreach (var opt in new[] { new WriteOptions(), new WriteOptions { WriteAscii = true }, new WriteOptions { Compressed = true } })
                    {
                        byte[] bytes = IO.WritePointCloudToMemory(pc, "pcd", opt);
                        Check(bytes.Length > 100 * 3 * 4, "pcd bytes");
                        using (var back = IO.ReadPointCloudFromMemory(bytes, "pcd"))
                        {
                            Check(back.Size == 100, "memory size");
                            AllNear(back.Points, pts, 1e-5, "memory points");
                        }
                    }
                    using (var buf = IO.WritePointCloudToNativeBuffer(pc, "ply"))
                    {
                        long size;
                        IntPtr p = buf.View(out size);
                        var bytes = buf.ToArray();
                        Check(size == bytes.Length && size > 0, "buffer size");
                        var viewed = new byte[size];
                        Marshal.Copy(p, viewed, 0, (int)size);
                        Check(viewed.SequenceEqual(bytes), "buffer view == copy");
                        Check(System.Text.Encoding.ASCII.GetString(bytes, 0, 3) == "ply", "ply magic");
                    }
                }
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("exceptions on bad input", () =>
        {
            using (var pc = new PointCloud(new double[] { 0, 0, 0, 1, 1, 1 }))
            {
                ThrowsStatus(Status.InvalidArgument, () => pc.VoxelDownSample(double.NaN), "NaN voxel size");
                ThrowsStatus(Status.InvalidArgument, () => pc.VoxelDownSample(-1), "negative voxel size");
                ThrowsStatus(Status.InvalidArgument, () => pc.SelectByIndex(new[] { 5 }), "index out of range");
                Check(Library.LastErrorMessage.Length > 0, "last error message kept");
                Check(Library.LastErrorCode == Status.InvalidArgument, "last error code");
                Library.ClearError();
                Check(Library.LastErrorCode == Status.Ok && Library.LastErrorMessage == "", "cleared");
            }
            ThrowsStatus(Status.IO, () => IO.ReadPointCloud("/nonexistent/dir/none.pcd"), "missing file");
            ThrowsStatus(Status.Parse, () => IO.ReadPointCloudFromMemory(System.Text.Encoding.ASCII.GetBytes("ply\nformat garbage\n"), "ply"), "malformed ply");
            ThrowsStatus(Status.Parse, () => IO.ReadPointCloudFromMemory(System.Text.Encoding.ASCII.GetBytes("# .PCD v0.7\nFIELDS x y\nPOINTS x\n"), "pcd"), "malformed pcd");
            Throws<ArgumentNullException>(() => IO.ReadPointCloudFromMemory(null, "ply"), "null bytes");
            Throws<O3dException>(() => Library.NumThreads = -1, "negative threads");
            var e = Throws<O3dException>(() => IO.ReadPointCloud("/nonexistent/x.pcd"), "message");
            Check(e.Message.Contains("O3D_ERROR_IO"), "message names the status: " + e.Message);
        });

        Run("disposed objects throw, Dispose is idempotent", () =>
        {
            var pc = new PointCloud(new double[] { 1, 2, 3 });
            var tree = new KDTreeFlann(pc);
            pc.Dispose();
            Check(pc.IsDisposed, "disposed");
            pc.Dispose(); // idempotent
            Throws<ObjectDisposedException>(() => { var n = pc.Size; }, "Size after Dispose");
            Throws<ObjectDisposedException>(() => pc.VoxelDownSample(0.1), "VoxelDownSample after Dispose");
            Check(tree.Size == 1, "tree outlives its cloud");
            tree.Dispose(); tree.Dispose();
            Throws<ObjectDisposedException>(() => tree.SearchKnn(new double[] { 0, 0, 0 }, 1), "search after Dispose");
            // finalizer safety net: forgotten clouds are collected without crashing
            for (int i = 0; i < 100; i++) new PointCloud(new double[] { i, i, i });
            GC.Collect(); GC.WaitForPendingFinalizers();
        });

        Run("library settings, log handler", () =>
        {
            int old = Library.NumThreads;
            Library.NumThreads = 2;
            Check(Library.NumThreads == 2, "threads");
            Library.NumThreads = 0;
            Check(Library.NumThreads >= 1, "default threads");
            var lv = Library.VerbosityLevel;
            Library.VerbosityLevel = LogLevel.Debug;
            Check(Library.VerbosityLevel == LogLevel.Debug, "verbosity");
            var lines = new List<string>();
            Library.SetLogHandler((level, msg) => { lock (lines) lines.Add(level + ": " + msg); });
            using (var pc = new PointCloud(RandomPoints(50, 5)))
            using (var d = pc.VoxelDownSample(0.2)) { }
            try { IO.ReadPointCloud("/nonexistent/none.ply"); } catch (O3dException) { }
            Library.SetLogHandler(null); // back to stderr
            Library.VerbosityLevel = lv;
            Console.WriteLine("  (log handler received " + lines.Count + " line(s))");
        });

        Run("remove statistical / radius outliers", () =>
        {
            var pts = GridWithOutliers();
            using (var pc = new PointCloud(pts))
            {
                using (var r = pc.RemoveStatisticalOutlier(8, 2.0))
                {
                    Check(r.Indices.SequenceEqual(Range(0, 100)), "statistical: kept indices " + string.Join(",", r.Indices));
                    Check(r.Cloud.Size == 100, "statistical: kept cloud size");
                    AllNear(r.Cloud.Points, pts.Take(300).ToArray(), 0, "statistical: kept points");
                }
                using (var r = pc.RemoveRadiusOutlier(3, 0.15))
                {
                    Check(r.Indices.SequenceEqual(Range(0, 100)), "radius: kept indices " + string.Join(",", r.Indices));
                    AllNear(r.Cloud.Points, pts.Take(300).ToArray(), 0, "radius: kept points");
                }
                // every grid point has at most 8 others within 0.15: nothing survives nb_points = 9
                using (var r = pc.RemoveRadiusOutlier(9, 0.15))
                {
                    Check(r.Indices.Length == 0 && r.Cloud.Size == 0, "radius: none kept");
                }
                Check(pc.Size == 102, "input untouched");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveStatisticalOutlier(0, 2.0), "nb_neighbors 0");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveStatisticalOutlier(8, -1), "negative std_ratio");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveRadiusOutlier(3, 0), "radius 0");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveRadiusOutlier(0, 0.1), "nb_points 0");
            }
            using (var empty = new PointCloud())
                ThrowsStatus(Status.InvalidArgument, () => empty.RemoveStatisticalOutlier(8, 2.0), "empty cloud");
        });

        Run("crop to an axis-aligned box (inclusive, invert)", () =>
        {
            var pts = new double[] { 0, 0, 0,  1, 1, 1,  0.5, 0.5, 0.5,  2, 0, 0,  1, 1, 1.0001,  0.5, -1e-9, 0.5 };
            using (var pc = new PointCloud(pts))
            {
                pc.Colors = Enumerable.Range(0, 18).Select(i => i / 18.0).ToArray();
                double[] min = { 0, 0, 0 }, max = { 1, 1, 1 };
                using (var inside = pc.CropAabb(min, max))
                {
                    AllNear(inside.Points, new double[] { 0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5 }, 0, "inside (bounds inclusive)");
                    AllNear(inside.Colors, Enumerable.Range(0, 9).Select(i => i / 18.0).ToArray(), 0, "colors follow");
                }
                using (var outside = pc.CropAabb(min, max, invert: true))
                    AllNear(outside.Points, new double[] { 2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5 }, 0, "outside");
                ThrowsStatus(Status.InvalidArgument, () => pc.CropAabb(max, min), "min > max");
                ThrowsStatus(Status.InvalidArgument, () => pc.CropAabb(new double[] { 0, 0, double.NaN }, max), "NaN bound");
                Throws<ArgumentException>(() => pc.CropAabb(new double[] { 0, 0 }, max), "short bound");
                Throws<ArgumentNullException>(() => pc.CropAabb(null, max), "null bound");
            }
        });

        Run("segment_plane recovers a known plane", () =>
        {
            // z = 0.5 x + 0.2 y + 1  <=>  0.5 x + 0.2 y - z + 1 = 0; 400 inliers then 20 points >= 1.7 off it
            var p = new List<double>();
            for (int i = 0; i < 20; i++)
                for (int j = 0; j < 20; j++) { double x = i * 0.1, y = j * 0.1; p.Add(x); p.Add(y); p.Add(0.5 * x + 0.2 * y + 1); }
            for (int k = 0; k < 20; k++) { double x = (k % 5) * 0.4, y = (k / 5) * 0.5; p.Add(x); p.Add(y); p.Add(0.5 * x + 0.2 * y + 3 + 0.1 * k); }
            double norm = Math.Sqrt(0.25 + 0.04 + 1);
            var expected = new[] { 0.5 / norm, 0.2 / norm, -1 / norm, 1 / norm };
            using (var pc = new PointCloud(p.ToArray()))
            {
                var r = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42);
                Check(r.Inliers.SequenceEqual(Range(0, 400)), "inliers " + r.Inliers.Length);
                Check(r.Plane.Length == 4, "plane length");
                double sign = r.Plane[2] < 0 ? 1 : -1; // normal up to sign
                AllNear(r.Plane.Select(v => v * sign).ToArray(), expected, 1e-9, "plane");
                var again = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42);
                AllNear(again.Plane, r.Plane, 0, "same seed, same plane");
                Check(again.Inliers.SequenceEqual(r.Inliers), "same seed, same inliers");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(0.01, 2, 1000), "ransac_n 2");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(0.01, 3, 0), "0 iterations");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(-0.01, 3, 100), "negative threshold");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(0.01, 3, 100, 1.5), "probability > 1");
            }
        });

        Run("cluster_dbscan on separated blobs", () =>
        {
            // blob at (10, 0, 0): 0..26, a lone noise point: 27, blob at the origin: 28..54
            var pts = Blob(10, 0, 0).Concat(new double[] { 5, 5, 5 }).Concat(Blob(0, 0, 0)).ToArray();
            using (var pc = new PointCloud(pts))
            {
                var labels = pc.ClusterDbscan(0.15, 3);
                Check(labels.Length == 55, "one label per point");
                for (int i = 0; i < 55; i++)
                    Check(labels[i] == (i < 27 ? 0 : i == 27 ? -1 : 1), "label[" + i + "] = " + labels[i]);
                Check(pc.ClusterDbscan(0.05, 1).SequenceEqual(Range(0, 55)), "eps below the spacing: singletons");
                ThrowsStatus(Status.InvalidArgument, () => pc.ClusterDbscan(0, 3), "eps 0");
                ThrowsStatus(Status.InvalidArgument, () => pc.ClusterDbscan(0.1, -1), "min_points < 0");
            }
        });

        Run("mean, covariance and Mahalanobis distance (analytic)", () =>
        {
            // (1, 2, 3) +- (1, 0, 0), (0, 2, 0), (0, 0, 3): mean (1, 2, 3), covariance diag(1/3, 4/3, 3)
            var pts = new double[] { 2, 2, 3, 0, 2, 3, 1, 4, 3, 1, 0, 3, 1, 2, 6, 1, 2, 0 };
            using (var pc = new PointCloud(pts))
            {
                var mc = pc.ComputeMeanAndCovariance();
                AllNear(mc.Mean, new double[] { 1, 2, 3 }, 1e-12, "mean");
                AllNear(mc.Covariance, new double[] { 1.0 / 3, 0, 0, 0, 4.0 / 3, 0, 0, 0, 3 }, 1e-12, "covariance");
                var d = pc.ComputeMahalanobisDistance();
                AllNear(d, Enumerable.Repeat(Math.Sqrt(3), 6).ToArray(), 1e-9, "mahalanobis");
            }
            using (var empty = new PointCloud())
            {
                ThrowsStatus(Status.InvalidArgument, () => empty.ComputeMeanAndCovariance(), "empty mean");
                ThrowsStatus(Status.InvalidArgument, () => empty.ComputeMahalanobisDistance(), "empty mahalanobis");
            }
        });

        Run("Figure 1 on cloud_bin_0.pcd", () =>
        {
            string input = DataFile("open3d/Feature/cloud_bin_0.pcd");
            string dir = TempDir();
            try
            {
                using (var pcd = IO.ReadPointCloud(input))
                {
                    Check(pcd.Size == 3903, "input size " + pcd.Size + " (the PCD header says 3903)");
                    using (var down = pcd.VoxelDownSample(0.05))
                    {
                        // 2655: Open3D 0.20.0 voxel_down_sample(0.05) on the same file.
                        Check(down.Size == 2655, "down size " + down.Size);
                        down.EstimateNormals(SearchParam.Hybrid(0.1, 30));
                        Check(down.HasNormals, "normals");
                        var n = down.Normals;
                        for (int i = 0; i < n.Length / 3; i++)
                            Near(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2], 1, 1e-6, "unit normal");
                        string outPath = Path.Combine(dir, "down.ply");
                        IO.WritePointCloud(outPath, down);
                        using (var back = IO.ReadPointCloud(outPath))
                        {
                            Check(back.Size == down.Size, "same count after re-read");
                            Check(back.HasNormals, "normals written");
                        }
                    }
                }
            }
            finally { Directory.Delete(dir, true); }
        });

        GeometryTests();
        ShapesTests();
        RegistrationPipelineTests(); // RegistrationPipelineTest.cs

        if (skipped > 0) Console.WriteLine("(" + skipped + " skipped)");
        Console.WriteLine(passed + " passed, " + failed + " failed");
        return failed == 0 ? 0 : 1;
    }

    // ---- triangle meshes, images, cameras, RGB-D (trianglemesh.h, image.h, camera.h, rgbd.h, io.h) ----

    static double Dist(double[] p, int i, double x, double y, double z)
    {
        double dx = p[3 * i] - x, dy = p[3 * i + 1] - y, dz = p[3 * i + 2] - z;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }

    /// <summary>Every (x, y, z) of <paramref name="p"/> lies on the surface of the box [0,w]x[0,h]x[0,d].</summary>
    static void OnBoxSurface(double[] p, double w, double h, double d, string what)
    {
        for (int i = 0; i < p.Length / 3; i++)
        {
            double x = p[3 * i], y = p[3 * i + 1], z = p[3 * i + 2];
            Check(x >= -1e-9 && x <= w + 1e-9 && y >= -1e-9 && y <= h + 1e-9 && z >= -1e-9 && z <= d + 1e-9, what + ": inside " + i);
            double face = Math.Min(Math.Min(Math.Min(Math.Abs(x), Math.Abs(w - x)), Math.Min(Math.Abs(y), Math.Abs(h - y))),
                                   Math.Min(Math.Abs(z), Math.Abs(d - z)));
            Check(face < 1e-9, what + ": on a face " + i);
        }
    }

    // Synthetic depth for the back-projection tests: d(u, v) = 1 + 0.25 u + 0.5 v on a 4x3 image,
    // pixel (2, 1) invalid (0). Camera fx = 2, fy = 3, cx = 1.5, cy = 1.
    const int DW = 4, DH = 3;
    static double DepthAt(int u, int v) { return (u == 2 && v == 1) ? 0 : 1 + 0.25 * u + 0.5 * v; }
    static PinholeCameraIntrinsic DepthCamera() { return new PinholeCameraIntrinsic(DW, DH, 2, 3, 1.5, 1); }

    /// <summary>The analytic back-projection, row by row (Open3D's order), minus t (world = camera - t).</summary>
    static double[] ExpectedDepthPoints(double tx, double ty, double tz)
    {
        var pts = new List<double>();
        for (int v = 0; v < DH; v++)
            for (int u = 0; u < DW; u++)
            {
                double d = DepthAt(u, v);
                if (d <= 0) continue;
                pts.Add((u - 1.5) * d / 2 - tx); pts.Add((v - 1.0) * d / 3 - ty); pts.Add(d - tz);
            }
        return pts.ToArray();
    }

    static void GeometryTests()
    {
        Run("image: CreatePyramid halves each level and keeps a constant", () =>
        {
            var flat = new float[32];
            for (int i = 0; i < flat.Length; ++i) flat[i] = 0.5f;
            using (var img = Image.FromFloat(8, 4, 1, flat))
            {
                Image[] levels = img.CreatePyramid(3);
                Check(levels.Length == 3 && levels[1].Width == 4 && levels[2].Width == 2 && levels[2].Height == 1, "sizes");
                foreach (var level in levels)
                {
                    foreach (float v in level.ToFloatArray()) Check(v == 0.5f, "constant kept");
                    level.Dispose();
                }
            }
            using (var ramp = Image.FromFloat(4, 2, 1, new float[] { 0, 1, 2, 3, 0, 1, 2, 3 }))
            {
                Image[] plain = ramp.CreatePyramid(2, false);
                float[] half = plain[1].ToFloatArray();
                Check(half.Length == 2 && half[0] == 0.5f && half[1] == 2.5f, "2x2 means");
                foreach (var level in plain) level.Dispose();
            }
        });
        Run("mesh: create_box area 6, volume 1, 8 vertices, 12 triangles", () =>
        {
            using (var box = TriangleMesh.CreateBox())
            {
                Check(box.NumVertices == 8 && box.NumTriangles == 12, "counts " + box.NumVertices + "/" + box.NumTriangles);
                Check(box.HasVertices && box.HasTriangles && !box.HasTextures, "has arrays");
                Near(box.GetSurfaceArea(), 6, 1e-12, "area");
                Near(box.GetVolume(), 1, 1e-12, "volume");
                Check(box.IsWatertight() && box.IsOrientable() && box.IsEdgeManifold(false) && box.IsVertexManifold(), "closed manifold");
                Check(!box.IsSelfIntersecting(), "not self-intersecting");
                Check(box.EulerPoincareCharacteristic() == 2, "Euler characteristic of a sphere-like surface");
                AllNear(box.MinBound, new double[] { 0, 0, 0 }, 0, "min bound");
                AllNear(box.MaxBound, new double[] { 1, 1, 1 }, 0, "max bound");
                AllNear(box.Center, new double[] { 0.5, 0.5, 0.5 }, 1e-12, "center");
                var v = box.Vertices;
                for (int c = 0; c < 8; c++)
                {
                    double x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
                    bool found = false;
                    for (int i = 0; i < 8; i++) found |= Dist(v, i, x, y, z) == 0;
                    Check(found, "corner " + x + "," + y + "," + z);
                }
                foreach (int t in box.Triangles) Check(t >= 0 && t < 8, "triangle index in range");
            }
            using (var box = TriangleMesh.CreateBox(2, 3, 4))
            {
                Near(box.GetSurfaceArea(), 2 * (2 * 3 + 3 * 4 + 2 * 4), 1e-12, "area 2x3x4");
                Near(box.GetVolume(), 24, 1e-12, "volume 2x3x4");
            }
        });

        Run("mesh: primitives (counts recorded from Open3D 0.20, tools/reference/record_primitives.py)", () =>
        {
            Func<TriangleMesh, long, long, string, TriangleMesh> counts = (m, nv, nt, what) =>
            {
                Check(m.NumVertices == nv && m.NumTriangles == nt, what + ": " + m.NumVertices + "/" + m.NumTriangles);
                return m;
            };
            using (var m = counts(TriangleMesh.CreateSphere(), 762, 1520, "sphere"))
            {
                Check(m.EulerPoincareCharacteristic() == 2 && m.IsWatertight(), "sphere closed");
                var v = m.Vertices;
                for (int i = 0; i < v.Length / 3; i++) Near(Dist(v, i, 0, 0, 0), 1, 1e-12, "on the unit sphere");
            }
            using (var m = counts(TriangleMesh.CreateCylinder(), 102, 200, "cylinder")) { }
            using (var m = counts(TriangleMesh.CreateCone(), 22, 40, "cone")) { }
            using (var m = counts(TriangleMesh.CreateTorus(), 600, 1200, "torus"))
                Check(m.EulerPoincareCharacteristic() == 0, "torus Euler characteristic 0");
            using (var m = counts(TriangleMesh.CreateArrow(), 124, 240, "arrow")) { }
            using (var m = counts(TriangleMesh.CreateCoordinateFrame(), 1134, 2240, "frame"))
                Check(m.HasVertexColors, "frame colored");
            using (var m = counts(TriangleMesh.CreateTetrahedron(), 4, 4, "tetrahedron"))
            {
                // regular tetrahedron with circumradius 1: edge sqrt(8/3), area sqrt(3) a^2, volume a^3 / (6 sqrt 2)
                double a = Math.Sqrt(8.0 / 3);
                Near(m.GetSurfaceArea(), Math.Sqrt(3) * a * a, 1e-9, "tetrahedron area");
                Near(m.GetVolume(), a * a * a / (6 * Math.Sqrt(2)), 1e-9, "tetrahedron volume");
            }
            using (var m = counts(TriangleMesh.CreateOctahedron(), 6, 8, "octahedron"))
                Near(m.GetVolume(), 4.0 / 3, 1e-9, "octahedron volume (4/3 r^3)");
            using (var m = counts(TriangleMesh.CreateIcosahedron(), 12, 20, "icosahedron")) { }
        });

        Run("mesh: arrays in and out in bulk, normals, append, clusters", () =>
        {
            // a unit right triangle in z = 0 plus one in z = 1, shifted
            var verts = new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            using (var m = new TriangleMesh(verts, new[] { 0, 1, 2 }))
            {
                AllNear(m.Vertices, verts, 0, "vertices round trip");
                Check(m.Triangles.SequenceEqual(new[] { 0, 1, 2 }), "triangles round trip");
                Check(!m.HasVertexNormals && !m.HasTriangleNormals, "no normals yet");
                m.ComputeVertexNormals();
                Check(m.HasVertexNormals && m.HasTriangleNormals, "normals computed");
                AllNear(m.VertexNormals, new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1 }, 1e-12, "vertex normals +z");
                AllNear(m.TriangleNormals, new double[] { 0, 0, 1 }, 1e-12, "triangle normal +z");
                m.ComputeTriangleNormals(false);
                AllNear(m.TriangleNormals, new double[] { 0, 0, 1 }, 1e-12, "unnormalized normal = cross product (area 1/2 * 2)");
                m.VertexColors = new double[] { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
                Check(m.HasVertexColors, "colors");
                m.TriangleUvs = new double[] { 0, 0, 1, 0, 0, 1 };
                Check(m.HasTriangleUvs && m.TriangleUvs.Length == 6, "uvs (3 rows of 2 per triangle)");
                m.TriangleMaterialIds = new[] { 0 };
                Check(m.HasTriangleMaterialIds, "material ids");
                long rows;
                IntPtr view = m.ArrayView(MeshArray.Vertices, out rows);
                var viewed = new double[rows * 3];
                System.Runtime.InteropServices.Marshal.Copy(view, viewed, 0, viewed.Length);
                Check(rows == 3 && viewed.SequenceEqual(verts), "vertex view");
                IntPtr iview = m.IndexArrayView(MeshIndexArray.Triangles, out rows);
                var tri = new int[3];
                System.Runtime.InteropServices.Marshal.Copy(iview, tri, 0, 3);
                Check(rows == 1 && tri.SequenceEqual(new[] { 0, 1, 2 }), "triangle view");
                IntPtr mv = m.ArrayMutableView(MeshArray.Vertices, out rows);
                System.Runtime.InteropServices.Marshal.Copy(new double[] { 2 }, 0, mv + 3 * sizeof(double), 1);
                Near(m.Vertices[3], 2, 0, "write through the mutable view");
                IntPtr tv = m.IndexArrayMutableView(MeshIndexArray.Triangles, out rows);
                Check(tv != IntPtr.Zero && rows == 1, "mutable index view");
                Near(m.GetSurfaceArea(), 1, 1e-12, "area after moving a vertex");

                using (var copy = m.Clone())
                {
                    copy.Translate(new double[] { 0, 0, 1 });
                    m.Append(copy);
                }
                Check(m.NumVertices == 6 && m.NumTriangles == 2, "appended");
                Check(m.Triangles.SequenceEqual(new[] { 0, 1, 2, 3, 4, 5 }), "appended triangles re-indexed");
                var cl = m.ClusterConnectedTriangles();
                Check(cl.TriangleClusterIndices.SequenceEqual(new[] { 0, 1 }), "two clusters");
                Check(cl.ClusterNTriangles.SequenceEqual(new[] { 1, 1 }), "cluster sizes");
                AllNear(cl.ClusterArea, new double[] { 1, 1 }, 1e-12, "cluster areas");
                m.Clear();
                Check(m.NumVertices == 0 && m.NumTriangles == 0, "cleared");
            }
        });

        Run("mesh: clean-up, transforms, processing", () =>
        {
            // two triangles sharing an edge, with the shared vertices duplicated, and a degenerate one
            using (var m = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 },
                                            new[] { 0, 1, 2, 3, 4, 5, 0, 0, 1 }))
            {
                m.RemoveDegenerateTriangles();
                Check(m.NumTriangles == 2, "degenerate removed");
                m.RemoveDuplicatedVertices();
                Check(m.NumVertices == 4, "duplicates merged: " + m.NumVertices);
                Near(m.GetSurfaceArea(), 1, 1e-12, "area kept");
                Check(m.ClusterConnectedTriangles().ClusterNTriangles.Length == 1, "now edge-connected");
                m.RemoveDuplicatedTriangles().RemoveUnreferencedVertices().RemoveNonManifoldEdges().MergeCloseVertices(1e-9);
                Check(m.NumVertices == 4 && m.NumTriangles == 2, "nothing more to clean");
                Check(m.EulerPoincareCharacteristic() == 1, "a disc: V - E + F = 4 - 5 + 2");
                Check(m.IsEdgeManifold(true) && !m.IsEdgeManifold(false) && !m.IsWatertight(), "open surface");
                ThrowsStatus(Status.InvalidArgument, () => m.GetVolume(), "volume of an open mesh");
            }
            using (var box = TriangleMesh.CreateBox())
            {
                box.Translate(new double[] { 1, 2, 3 });
                AllNear(box.MinBound, new double[] { 1, 2, 3 }, 1e-12, "translated");
                box.Translate(new double[] { 0, 0, 0 }, false);
                AllNear(box.Center, new double[] { 0, 0, 0 }, 1e-12, "centered");
                box.Scale(2, new double[] { 0, 0, 0 });
                Near(box.GetSurfaceArea(), 24, 1e-9, "scaled area");
                box.Rotate(new double[] { 0, -1, 0, 1, 0, 0, 0, 0, 1 });
                Near(box.GetVolume(), 8, 1e-9, "rotated volume");
                box.Transform(new double[] { 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1 });
                double[] lo, hi;
                box.GetAxisAlignedBoundingBox(out lo, out hi);
                AllNear(lo, new double[] { 0, 0, 0 }, 1e-9, "aabb min"); AllNear(hi, new double[] { 2, 2, 2 }, 1e-9, "aabb max");
                box.PaintUniformColor(new double[] { 0.25, 0.5, 1 });
                AllNear(box.VertexColors.Take(3).ToArray(), new double[] { 0.25, 0.5, 1 }, 0, "painted");
                box.NormalizeNormals();
            }
            using (var box = TriangleMesh.CreateBox())
            {
                using (var sub = box.SubdivideMidpoint(1))
                {
                    // each of the 18 edges gets one midpoint; each triangle becomes four
                    Check(sub.NumVertices == 26 && sub.NumTriangles == 48, "midpoint counts");
                    Near(sub.GetSurfaceArea(), 6, 1e-12, "midpoint keeps the area");
                }
                using (var loop = box.SubdivideLoop(1))
                {
                    Check(loop.NumTriangles == 48 && loop.IsWatertight(), "loop counts");
                    Check(loop.GetSurfaceArea() < 6, "loop shrinks the box");
                }
                using (var crop = box.Crop(new double[] { -0.1, -0.1, -0.1 }, new double[] { 1.1, 1.1, 0.5 }))
                {
                    Check(crop.NumTriangles == 2 && crop.NumVertices == 4, "crop keeps the z = 0 face");
                    foreach (var z in crop.Vertices.Where((x, i) => i % 3 == 2)) Near(z, 0, 0, "cropped z");
                }
                using (var a = box.SamplePointsUniformly(500, false, 7))
                using (var b = box.SamplePointsUniformly(500, false, 7))
                {
                    Check(a.Size == 500, "500 samples");
                    Check(a.Points.SequenceEqual(b.Points), "same seed, same samples");
                    OnBoxSurface(a.Points, 1, 1, 1, "uniform samples");
                }
                using (var pd = box.SamplePointsPoissonDisk(100, 5, false, 3))
                {
                    Check(pd.Size == 100, "poisson disk count " + pd.Size);
                    OnBoxSurface(pd.Points, 1, 1, 1, "poisson samples");
                }
                using (var s = box.FilterSmoothSimple(1)) Check(s.NumVertices == 8 && s.NumTriangles == 12, "smooth simple keeps topology");
                using (var s = box.FilterSmoothLaplacian(2)) Check(s.NumVertices == 8, "laplacian keeps topology");
                using (var s = box.FilterSmoothTaubin(2)) Check(s.NumVertices == 8, "taubin keeps topology");
                using (var s = box.SimplifyVertexClustering(10)) Check(s.NumTriangles < 12, "one voxel collapses the box");
            }
            using (var sphere = TriangleMesh.CreateSphere())
            using (var dec = sphere.SimplifyQuadricDecimation(100))
                Check(dec.NumTriangles <= 100 && dec.NumTriangles > 0, "decimated to " + dec.NumTriangles);
        });

        Run("mesh: written then read back equal (PLY/OFF in memory, PLY/OBJ files)", () =>
        {
            using (var box = TriangleMesh.CreateBox())
            {
                var colors = new double[24];
                for (int i = 0; i < 24; i++) colors[i] = (i * 10 % 256) / 255.0; // exact in 8 bits
                box.VertexColors = colors;
                foreach (var fmt in new[] { "ply", "off" })
                {
                    byte[] bytes = IO.WriteTriangleMeshToMemory(box, fmt);
                    Check(bytes.Length > 0, fmt + " bytes");
                    using (var back = IO.ReadTriangleMeshFromMemory(bytes, fmt))
                    {
                        AllNear(back.Vertices, box.Vertices, 1e-6, fmt + " vertices");
                        Check(back.Triangles.SequenceEqual(box.Triangles), fmt + " triangles");
                        if (fmt == "ply") AllNear(back.VertexColors, colors, 1e-9, "ply colors");
                    }
                }
                using (var nb = IO.WriteTriangleMeshToNativeBuffer(box, "ply", new MeshWriteOptions { WriteAscii = true }))
                    Check(System.Text.Encoding.ASCII.GetString(nb.ToArray()).Contains("format ascii"), "ascii ply");
                string dir = TempDir();
                try
                {
                    string ply = Path.Combine(dir, "box.ply");
                    IO.WriteTriangleMesh(ply, box, null, new MeshWriteOptions { WriteAscii = true, WriteVertexColors = false });
                    using (var back = IO.ReadTriangleMesh(ply, null, new MeshReadOptions { EnablePostProcessing = false }))
                    {
                        Check(back.NumVertices == 8 && back.NumTriangles == 12 && !back.HasVertexColors, "ply file, no colors");
                        AllNear(back.Vertices, box.Vertices, 1e-6, "ply file vertices");
                    }
                    string obj = Path.Combine(dir, "box.obj");
                    IO.WriteTriangleMesh(obj, box);
                    using (var back = IO.ReadTriangleMesh(obj))
                    {
                        Check(back.NumTriangles == 12, "obj triangles");
                        Near(back.GetSurfaceArea(), 6, 1e-9, "obj area");
                    }
                }
                finally { Directory.Delete(dir, true); }
            }
        });

        Run("image: PNG round trip in memory and on disk, typed pixels", () =>
        {
            var px = new byte[5 * 4 * 3];
            for (int i = 0; i < px.Length; i++) px[i] = (byte)(i * 7);
            using (var img = Image.FromBytes(5, 4, 3, 1, px))
            {
                Check(img.Width == 5 && img.Height == 4 && img.NumChannels == 3 && img.BytesPerChannel == 1, "shape");
                Check(img.Data.SequenceEqual(px), "data copy");
                byte[] png = IO.WriteImageToMemory(img, "png");
                Check(png.Length > 8 && png[0] == 0x89 && png[1] == (byte)'P' && png[2] == (byte)'N' && png[3] == (byte)'G', "PNG signature");
                using (var back = IO.ReadImageFromMemory(png, "png"))
                {
                    Check(back.Width == 5 && back.Height == 4 && back.NumChannels == 3 && back.BytesPerChannel == 1, "png shape");
                    Check(back.Data.SequenceEqual(px), "png pixels equal");
                }
                string dir = TempDir();
                try
                {
                    string path = Path.Combine(dir, "img.png");
                    IO.WriteImage(path, img);
                    using (var back = IO.ReadImage(path)) Check(back.Data.SequenceEqual(px), "png file pixels equal");
                    string ppm = Path.Combine(dir, "img.ppm");
                    IO.WriteImage(ppm, img);
                    using (var back = IO.ReadImage(ppm)) Check(back.Data.SequenceEqual(px), "ppm file pixels equal");
                }
                finally { Directory.Delete(dir, true); }
                long size;
                IntPtr v = img.DataView(out size);
                Check(v != IntPtr.Zero && size == px.Length, "data view");
                IntPtr mv = img.DataMutableView(out size);
                System.Runtime.InteropServices.Marshal.WriteByte(mv, 0, 200);
                Check(img.Data[0] == 200, "write through the mutable view");
                using (var c = img.Clone()) Check(c.Data.SequenceEqual(img.Data), "clone");
            }
            var depth = new ushort[] { 0, 1, 1000, 65535, 300, 42 };
            using (var d16 = Image.FromUInt16(3, 2, 1, depth))
            using (var back = IO.ReadImageFromMemory(IO.WriteImageToMemory(d16, "png"), "png"))
            {
                Check(back.BytesPerChannel == 2 && back.ToUInt16Array().SequenceEqual(depth), "16-bit png round trip");
            }
            using (var gray = Image.FromBytes(8, 8, 1, 1, Enumerable.Repeat((byte)128, 64).ToArray()))
            using (var back = IO.ReadImageFromMemory(IO.WriteImageToMemory(gray, "jpg", 95), "jpg"))
            {
                Check(back.Width == 8 && back.NumChannels == 1, "jpeg shape");
                foreach (var b in back.Data) Check(Math.Abs(b - 128) <= 2, "jpeg of a flat image stays flat");
            }
        });

        Run("image: flips, float conversion, depth conversion, filters", () =>
        {
            using (var row = Image.FromBytes(3, 1, 1, 1, new byte[] { 1, 2, 3 }))
            using (var flipped = row.FlipHorizontal())
            using (var same = row.FlipVertical())
            {
                Check(flipped.Data.SequenceEqual(new byte[] { 3, 2, 1 }), "flip horizontal");
                Check(same.Data.SequenceEqual(new byte[] { 1, 2, 3 }), "flip vertical of one row");
            }
            using (var col = Image.FromBytes(1, 3, 1, 1, new byte[] { 1, 2, 3 }))
            using (var flipped = col.FlipVertical())
                Check(flipped.Data.SequenceEqual(new byte[] { 3, 2, 1 }), "flip vertical");
            using (var g = Image.FromBytes(3, 1, 1, 1, new byte[] { 0, 255, 51 }))
            using (var f = g.CreateFloatImage())
            {
                Check(f.NumChannels == 1 && f.BytesPerChannel == 4, "float image");
                AllNear(f.ToFloatArray().Select(x => (double)x).ToArray(), new[] { 0, 1, 0.2 }, 1e-6, "8-bit / 255");
            }
            using (var rgb = Image.FromBytes(1, 1, 3, 1, new byte[] { 255, 0, 0 }))
            {
                using (var w = rgb.CreateFloatImage(ImageConvertType.Weighted)) Near(w.ToFloatArray()[0], 0.299, 1e-6, "weighted gray");
                using (var e = rgb.CreateFloatImage(ImageConvertType.Equal)) Near(e.ToFloatArray()[0], 1.0 / 3, 1e-6, "equal gray");
            }
            using (var raw = Image.FromUInt16(3, 1, 1, new ushort[] { 500, 4000, 1500 }))
            using (var m = raw.ConvertDepthToFloat(1000, 3.0))
                AllNear(m.ToFloatArray().Select(x => (double)x).ToArray(), new[] { 0.5, 0, 1.5 }, 1e-6, "depth in metres, truncated");
            using (var flat = Image.FromFloat(5, 4, 1, Enumerable.Repeat(0.5f, 20).ToArray()))
            {
                foreach (ImageFilterType t in new[] { ImageFilterType.Gaussian3, ImageFilterType.Gaussian5, ImageFilterType.Gaussian7 })
                    using (var f = flat.Filter(t))
                        foreach (var x in f.ToFloatArray()) Near(x, 0.5, 1e-6, t + " of a flat image");
                foreach (ImageFilterType t in new[] { ImageFilterType.Sobel3Dx, ImageFilterType.Sobel3Dy })
                    using (var f = flat.Filter(t))
                        foreach (var x in f.ToFloatArray()) Near(x, 0, 1e-6, t + " of a flat image");
            }
            using (var img = Image.FromFloat(4, 2, 1, new float[] { 1, 3, 5, 7, 1, 3, 5, 7 }))
            using (var half = img.Downsample())
            {
                Check(half.Width == 2 && half.Height == 1, "half size");
                AllNear(half.ToFloatArray().Select(x => (double)x).ToArray(), new double[] { 2, 6 }, 1e-6, "2x2 means");
            }
        });

        Run("camera: intrinsic presets, trajectory, JSON round trips", () =>
        {
            var ps = PinholeCameraIntrinsic.FromPreset(PinholeCameraIntrinsicParameters.PrimeSenseDefault);
            Check(ps.Equals(new PinholeCameraIntrinsic(640, 480, 525, 525, 319.5, 239.5)), "PrimeSense: " + ps);
            AllNear(ps.IntrinsicMatrix, new[] { 525, 0, 319.5, 0, 525, 239.5, 0, 0, 1 }, 0, "intrinsic matrix");
            var k2d = PinholeCameraIntrinsic.FromPreset(PinholeCameraIntrinsicParameters.Kinect2DepthCameraDefault);
            Check(k2d.Equals(new PinholeCameraIntrinsic(512, 424, 365.456, 365.456, 254.878, 205.395)), "Kinect2 depth: " + k2d);
            var k2c = PinholeCameraIntrinsic.FromPreset(PinholeCameraIntrinsicParameters.Kinect2ColorCameraDefault);
            Check(k2c.Width == 1920 && k2c.Height == 1080, "Kinect2 color size");
            Near(k2c.Fx, 1059.9718, 1e-9, "fx"); Near(k2c.Cx, 975.7193, 1e-9, "cx"); Near(k2c.Cy, 545.9533, 1e-9, "cy");
            Check(ps.GetHashCode() == new PinholeCameraIntrinsic(640, 480, 525, 525, 319.5, 239.5).GetHashCode(), "hash");
            ThrowsStatus(Status.InvalidArgument, () => PinholeCameraIntrinsic.FromPreset((PinholeCameraIntrinsicParameters)99), "bad preset");

            var pose = new double[] { 0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1 };
            string dir = TempDir();
            try
            {
                using (var traj = new PinholeCameraTrajectory())
                {
                    Check(traj.Count == 0, "empty");
                    traj.Append(ps, pose);
                    traj.Append(new PinholeCameraParameters(k2d, ApplyTransformIdentity()));
                    Check(traj.Count == 2, "two poses");
                    Check(traj[0].Intrinsic.Equals(ps), "intrinsic back");
                    AllNear(traj[0].Extrinsic, pose, 0, "extrinsic back");
                    ThrowsStatus(Status.InvalidArgument, () => { var p = traj[5]; }, "index out of range");
                    var bad = (double[])pose.Clone(); bad[15] = 2;
                    ThrowsStatus(Status.InvalidArgument, () => traj.Append(ps, bad), "last row not (0,0,0,1)");
                    string json = Path.Combine(dir, "traj.json");
                    IO.WritePinholeCameraTrajectory(json, traj);
                    using (var back = IO.ReadPinholeCameraTrajectory(json))
                    {
                        var list = back.Parameters;
                        Check(list.Count == 2 && list[0].Intrinsic.Equals(ps) && list[1].Intrinsic.Equals(k2d), "json intrinsics");
                        AllNear(list[0].Extrinsic, pose, 1e-12, "json extrinsic");
                    }
                    string log = Path.Combine(dir, "traj.log");
                    IO.WritePinholeCameraTrajectory(log, traj, "log");
                    using (var back = IO.ReadPinholeCameraTrajectory(log, "log"))
                    {
                        Check(back.Count == 2, "log poses");
                        AllNear(back[0].Extrinsic, pose, 1e-9, "log extrinsic");
                        Check(back[0].Intrinsic.Equals(ps), "log intrinsic is the PrimeSense default");
                    }
                    traj.Clear();
                    Check(traj.Count == 0, "cleared");
                }
                string ipath = Path.Combine(dir, "intrinsic.json");
                IO.WritePinholeCameraIntrinsic(ipath, k2d);
                Check(IO.ReadPinholeCameraIntrinsic(ipath).Equals(k2d), "intrinsic json round trip");
                string ppath = Path.Combine(dir, "params.json");
                IO.WritePinholeCameraParameters(ppath, new PinholeCameraParameters(ps, pose));
                var pp = IO.ReadPinholeCameraParameters(ppath);
                Check(pp.Intrinsic.Equals(ps), "parameters intrinsic");
                AllNear(pp.Extrinsic, pose, 1e-12, "parameters extrinsic");
                ThrowsStatus(Status.IO, () => IO.ReadPinholeCameraIntrinsic(Path.Combine(dir, "none.json")), "missing json");
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("rgbd: synthetic depth image back-projected to the analytic points", () =>
        {
            var metres = new float[DW * DH];
            var mm = new ushort[DW * DH];
            for (int v = 0; v < DH; v++)
                for (int u = 0; u < DW; u++) { metres[v * DW + u] = (float)DepthAt(u, v); mm[v * DW + u] = (ushort)(DepthAt(u, v) * 1000); }
            var cam = DepthCamera();
            using (var fdepth = Image.FromFloat(DW, DH, 1, metres))
            using (var udepth = Image.FromUInt16(DW, DH, 1, mm))
            {
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam))
                    AllNear(pc.Points, ExpectedDepthPoints(0, 0, 0), 1e-6, "float depth");
                using (var pc = PointCloud.CreateFromDepthImage(udepth, cam, null, 1000))
                    AllNear(pc.Points, ExpectedDepthPoints(0, 0, 0), 1e-6, "uint16 depth / 1000");
                var ext = new double[] { 1, 0, 0, 0.5, 0, 1, 0, -1, 0, 0, 1, 2, 0, 0, 0, 1 };
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, ext))
                    AllNear(pc.Points, ExpectedDepthPoints(0.5, -1, 2), 1e-6, "extrinsic inverted");
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, 1000, 1000, 2))
                    Check(pc.Size == 4, "stride 2 keeps pixels (0,0),(2,0),(0,2),(2,2): " + pc.Size);
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, 1000, 2.0))
                    // Open3D drops depth >= depth_trunc: the five pixels at 2 m or deeper
                    Check(pc.Size == ExpectedDepthPoints(0, 0, 0).Length / 3 - 5, "depth_trunc 2: " + pc.Size);
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, 1000, 1000, 1, false))
                {
                    Check(pc.Size == DW * DH, "organised cloud");
                    Check(double.IsNaN(pc.Points[3 * (1 * DW + 2)]), "invalid pixel is NaN");
                }

                var color = new byte[DW * DH * 3];
                for (int i = 0; i < DW * DH; i++) { color[3 * i] = (byte)(10 * i); color[3 * i + 1] = 100; color[3 * i + 2] = 200; }
                using (var cimg = Image.FromBytes(DW, DH, 3, 1, color))
                {
                    using (var rgbd = RGBDImage.CreateFromColorAndDepth(cimg, udepth, 1000, 3.0, false))
                    {
                        using (var d = rgbd.Depth)
                            AllNear(d.ToFloatArray().Select(x => (double)x).ToArray(), metres.Select(x => (double)x).ToArray(), 1e-6, "rgbd depth in metres");
                        using (var c = rgbd.Color) Check(c.NumChannels == 3 && c.Data.SequenceEqual(color), "color kept");
                        using (var pc = PointCloud.CreateFromRGBDImage(rgbd, cam))
                        {
                            AllNear(pc.Points, ExpectedDepthPoints(0, 0, 0), 1e-6, "rgbd points");
                            var expect = new List<double>();
                            for (int i = 0; i < DW * DH; i++)
                                if (metres[i] > 0) { expect.Add(color[3 * i] / 255.0); expect.Add(100 / 255.0); expect.Add(200 / 255.0); }
                            AllNear(pc.Colors, expect.ToArray(), 1e-6, "rgbd colors");
                        }
                    }
                    using (var rgbd = RGBDImage.CreateFromColorAndDepth(cimg, udepth))
                    using (var c = rgbd.Color)
                    {
                        Check(c.NumChannels == 1 && c.BytesPerChannel == 4, "intensity image");
                        Near(c.ToFloatArray()[0], (0.587 * 100 + 0.114 * 200) / 255.0, 1e-5, "weighted intensity");
                    }
                    // Redwood: uint16 millimetres truncated at 4 m
                    var far = (ushort[])mm.Clone(); far[0] = 4500;
                    using (var fd = Image.FromUInt16(DW, DH, 1, far))
                    using (var rgbd = RGBDImage.CreateFromRedwoodFormat(cimg, fd))
                    using (var d = rgbd.Depth)
                    {
                        var got = d.ToFloatArray();
                        Near(got[0], 0, 0, "4.5 m truncated"); Near(got[1], 1.25, 1e-6, "1.25 m kept");
                    }
                    using (var rgbd = RGBDImage.CreateFromTUMFormat(cimg, udepth))
                    using (var d = rgbd.Depth) Near(d.ToFloatArray()[1], 1250 / 5000.0, 1e-6, "TUM depth scale 5000");
                    using (var rgbd = RGBDImage.CreateFromSUNFormat(cimg, udepth)) Check(rgbd.Depth.Width == DW, "SUN reader");
                    using (var rgbd = RGBDImage.CreateFromNYUFormat(cimg, udepth)) Check(rgbd.Depth.Height == DH, "NYU reader");
                    using (var small = new Image(2, 2, 1, 2))
                        ThrowsStatus(Status.InvalidArgument, () => RGBDImage.CreateFromColorAndDepth(cimg, small), "size mismatch");
                    ThrowsStatus(Status.InvalidArgument, () => PointCloud.CreateFromDepthImage(cimg, cam), "3-channel depth");
                }
            }
        });

        Run("mesh: errors for bad input and misuse", () =>
        {
            ThrowsStatus(Status.InvalidArgument, () => TriangleMesh.CreateBox(-1, 1, 1), "negative box");
            ThrowsStatus(Status.InvalidArgument, () => TriangleMesh.CreateSphere(1, 0), "sphere resolution 0");
            using (var m = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new[] { 0, 1, 5 }))
            {
                ThrowsStatus(Status.InvalidArgument, () => m.ComputeVertexNormals(), "triangle index out of range");
                ThrowsStatus(Status.InvalidArgument, () => m.GetSurfaceArea(), "area with a bad index");
                ThrowsStatus(Status.InvalidArgument, () => m.SamplePointsUniformly(10), "sampling with a bad index");
                ThrowsStatus(Status.InvalidArgument, () => m.MergeCloseVertices(double.NaN), "NaN eps");
                ThrowsStatus(Status.InvalidArgument, () => m.GetTexture(0), "no texture 0");
                Throws<ArgumentException>(() => m.Vertices = new double[] { 1, 2 }, "length not a multiple of 3");
                Throws<ArgumentNullException>(() => m.Triangles = null, "null triangles");
                Throws<ArgumentNullException>(() => m.Append(null), "null other");
            }
            ThrowsStatus(Status.IO, () => IO.ReadTriangleMesh("/nonexistent/dir/none.ply"), "missing mesh file");
            ThrowsStatus(Status.Parse, () => IO.ReadTriangleMeshFromMemory(System.Text.Encoding.ASCII.GetBytes("ply\nformat garbage\n"), "ply"), "malformed ply mesh");
            using (var box = TriangleMesh.CreateBox())
                ThrowsStatus(Status.Unsupported, () => IO.WriteTriangleMeshToMemory(box, "nope"), "unknown mesh format");
        });

        Run("image, camera, rgbd: errors for bad input and misuse", () =>
        {
            ThrowsStatus(Status.InvalidArgument, () => new Image(0, 0), "empty image");
            ThrowsStatus(Status.InvalidArgument, () => new Image(2, 2, 2, 1), "2 channels");
            ThrowsStatus(Status.InvalidArgument, () => Image.FromBytes(2, 2, 1, 1, new byte[3]), "data size mismatch");
            ThrowsStatus(Status.Parse, () => IO.ReadImageFromMemory(new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G', 1, 2, 3 }, "png"), "truncated png");
            ThrowsStatus(Status.IO, () => IO.ReadImage("/nonexistent/dir/none.png"), "missing image");
            using (var img = new Image(2, 2))
                ThrowsStatus(Status.InvalidArgument, () => img.Filter(ImageFilterType.Gaussian3), "filter needs float");
            using (var f = Image.FromFloat(2, 2, 1, new float[4]))
                Throws<O3dException>(() => IO.WriteImageToMemory(f, "png"), "float images are not written");
            Throws<ArgumentNullException>(() => IO.WriteImage("x.png", null), "null image");
            Throws<ArgumentNullException>(() => PointCloud.CreateFromDepthImage(null, DepthCamera()), "null depth");

            var image = new Image(2, 2);
            var traj = new PinholeCameraTrajectory();
            image.Dispose(); traj.Dispose(); image.Dispose();
            Throws<ObjectDisposedException>(() => { var w = image.Width; }, "image after Dispose");
            Throws<ObjectDisposedException>(() => { var c = traj.Count; }, "trajectory after Dispose");
            for (int i = 0; i < 50; i++) new Image(4, 4);
            GC.Collect(); GC.WaitForPendingFinalizers();
        });

        Run("mesh: textures, Dispose", () =>
        {
            var mesh = TriangleMesh.CreateBox();
            var tex = new Image(1, 1, 3, 1);
            mesh.AddTexture(tex);
            tex.Dispose();
            Check(mesh.TextureCount == 1 && mesh.HasTextures, "texture copied in");
            using (var t = mesh.GetTexture(0)) Check(t.Width == 1 && t.NumChannels == 3, "texture back");
            mesh.ClearTextures();
            Check(mesh.TextureCount == 0, "textures cleared");
            mesh.Dispose(); mesh.Dispose();
            Throws<ObjectDisposedException>(() => { var n = mesh.NumVertices; }, "mesh after Dispose");
            for (int i = 0; i < 50; i++) TriangleMesh.CreateBox();
            GC.Collect(); GC.WaitForPendingFinalizers();
        });
    }

    // ---- oriented boxes, hulls, line sets, voxel grids, octrees, covariances (the same in ShapesTest.java) ----
    // Orders and indices checked against Open3D 0.20: tools/reference/record_shapes_bindings.py.

    // The 8 corners of [0,1]^3 (index = x + 2y + 4z) then 5 interior points.
    static double[] CubeWithInterior()
    {
        var p = new List<double>();
        for (int c = 0; c < 8; c++) { p.Add(c & 1); p.Add((c >> 1) & 1); p.Add((c >> 2) & 1); }
        p.AddRange(new double[] { 0.5, 0.5, 0.5, 0.2, 0.3, 0.4, 0.9, 0.1, 0.5, 0.7, 0.7, 0.2, 0.1, 0.8, 0.9 });
        return p.ToArray();
    }

    static bool SameRows(double[] a, double[] b, double tol)
    {
        if (a.Length != b.Length) return false;
        var used = new bool[b.Length / 3];
        for (int i = 0; i < a.Length / 3; i++)
        {
            bool found = false;
            for (int j = 0; j < b.Length / 3 && !found; j++)
                if (!used[j] && Math.Abs(a[3 * i] - b[3 * j]) <= tol && Math.Abs(a[3 * i + 1] - b[3 * j + 1]) <= tol &&
                    Math.Abs(a[3 * i + 2] - b[3 * j + 2]) <= tol) { used[j] = true; found = true; }
            if (!found) return false;
        }
        return true;
    }

    static double Det3(double[] m, int o)
    {
        return m[o] * (m[o + 4] * m[o + 8] - m[o + 5] * m[o + 7]) - m[o + 1] * (m[o + 3] * m[o + 8] - m[o + 5] * m[o + 6]) +
               m[o + 2] * (m[o + 3] * m[o + 7] - m[o + 4] * m[o + 6]);
    }

    static void ShapesTests()
    {
        Run("convex hull of a cube with interior points", () =>
        {
            var pts = CubeWithInterior();
            using (var pc = new PointCloud(pts))
            using (var hull = pc.ComputeConvexHull())
            {
                Check(hull.Mesh.NumVertices == 8 && hull.Mesh.NumTriangles == 12, "8 vertices, 12 triangles: " +
                      hull.Mesh.NumVertices + ", " + hull.Mesh.NumTriangles);
                Near(hull.Mesh.GetVolume(), 1, 1e-12, "volume");
                Check(hull.Mesh.IsWatertight(), "watertight");
                Check(hull.PointIndices.Length == 8, "one index per vertex");
                var v = hull.Mesh.Vertices;
                for (int i = 0; i < 8; i++)
                {
                    int k = hull.PointIndices[i];
                    Check(k >= 0 && k < 8, "hull vertex " + i + " is a corner, got index " + k);
                    AllNear(new[] { v[3 * i], v[3 * i + 1], v[3 * i + 2] }, new[] { pts[3 * k], pts[3 * k + 1], pts[3 * k + 2] }, 0, "vertex = its point");
                }
                Check(hull.PointIndices.Distinct().Count() == 8, "distinct corners");
            }
            using (var box = TriangleMesh.CreateBox(1, 2, 3))
            using (var hull = box.ComputeConvexHull())
            {
                Near(hull.Mesh.GetVolume(), 6, 1e-12, "mesh hull volume");
                Check(hull.Mesh.NumTriangles == 12 && hull.PointIndices.Length == 8, "mesh hull counts");
            }
            using (var flat = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0 }))
            {
                Throws<O3dException>(() => flat.ComputeConvexHull(), "coplanar points without joggle");
                using (var j = flat.ComputeConvexHull(true)) Check(j.Mesh.NumTriangles > 0, "joggled coplanar hull");
            }
            using (var three = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }))
                Throws<O3dException>(() => three.ComputeConvexHull(true), "3 points");
            using (var empty = new PointCloud()) Throws<O3dException>(() => empty.ComputeConvexHull(), "empty cloud");
        });

        Run("hidden point removal", () =>
        {
            // Points on the unit sphere seen from (0, 0, 5): only the cap facing the camera (z > 0.2) is visible.
            var p = new List<double>();
            var r = new Random(3);
            while (p.Count < 3 * 400)
            {
                double x = 2 * r.NextDouble() - 1, y = 2 * r.NextDouble() - 1, z = 2 * r.NextDouble() - 1, n = Math.Sqrt(x * x + y * y + z * z);
                if (n < 0.1 || n > 1) continue;
                p.Add(x / n); p.Add(y / n); p.Add(z / n);
            }
            var pts = p.ToArray();
            using (var pc = new PointCloud(pts))
            using (var res = pc.HiddenPointRemoval(new double[] { 0, 0, 5 }, 500))
            {
                Check(res.PointIndices.Length > 20 && res.PointIndices.Length < 250, "visible count " + res.PointIndices.Length);
                foreach (int i in res.PointIndices)
                {
                    Check(i >= 0 && i < 400, "index in range " + i);
                    Check(pts[3 * i + 2] > 0, "visible point faces the camera: z = " + pts[3 * i + 2]);
                }
                Check(res.Mesh.NumTriangles > 0, "hull mesh");
                ThrowsStatus(Status.InvalidArgument, () => pc.HiddenPointRemoval(new double[] { 0, 0, 5 }, -1), "negative radius");
                Throws<ArgumentException>(() => pc.HiddenPointRemoval(new double[] { 0, 0 }, 1), "camera of 2 values");
            }
        });

        Run("oriented bounding box", () =>
        {
            var aabb = OrientedBoundingBox.CreateFromAxisAlignedBoundingBox(new double[] { 0, 0, 0 }, new double[] { 1, 2, 3 });
            AllNear(aabb.Center, new[] { 0.5, 1, 1.5 }, 1e-15, "center");
            AllNear(aabb.Extent, new double[] { 1, 2, 3 }, 1e-15, "extent");
            AllNear(aabb.R, new double[] { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, 0, "R");
            Near(aabb.Volume, 6, 1e-12, "volume");
            AllNear(aabb.GetBoxPoints(), new double[] { 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 1, 2, 3, 0, 2, 3, 1, 0, 3, 1, 2, 0 }, 1e-12,
                    "box points in Open3D's order");
            Check(aabb.GetPointIndicesWithinBoundingBox(new double[] { 0.5, 0.5, 0.5, 2, 0, 0, 1, 2, 3, -0.1, 1, 1 })
                      .SequenceEqual(new[] { 0, 2 }), "indices within (boundary included)");

            // PCA box of a 2 x 3 x 4 block: volume 24, extents {2, 3, 4}, orthonormal R.
            var pts = new List<double>();
            for (int c = 0; c < 8; c++) { pts.Add(2 * (c & 1)); pts.Add(3 * ((c >> 1) & 1)); pts.Add(4 * ((c >> 2) & 1)); }
            pts.AddRange(new double[] { 1, 1.5, 2, 0.5, 0.5, 0.5 });
            var obb = OrientedBoundingBox.CreateFromPoints(pts.ToArray());
            Near(obb.Volume, 24, 1e-9, "PCA volume");
            var e = obb.Extent; Array.Sort(e);
            AllNear(e, new double[] { 2, 3, 4 }, 1e-9, "PCA extents");
            AllNear(obb.Center, new[] { 1, 1.5, 2 }, 1e-9, "PCA center");
            var R = obb.R;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    Near(R[i] * R[j] + R[3 + i] * R[3 + j] + R[6 + i] * R[6 + j], i == j ? 1 : 0, 1e-9, "R^T R");
            Check(SameRows(obb.GetBoxPoints(), pts.Take(24).ToArray(), 1e-9), "PCA box corners are the block's");
            using (var pc = new PointCloud(pts.ToArray()))
                Near(pc.GetOrientedBoundingBox().Volume, 24, 1e-9, "cloud OBB volume");
            using (var mesh = TriangleMesh.CreateBox(2, 3, 4))
                Near(mesh.GetOrientedBoundingBox().Volume, 24, 1e-9, "mesh OBB volume");

            Throws<O3dException>(() => OrientedBoundingBox.CreateFromPoints(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }), "3 points");
            Throws<O3dException>(() => OrientedBoundingBox.CreateFromPoints(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 }), "planar");
            Near(OrientedBoundingBox.CreateFromPoints(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 }, true).Volume, 0, 1e-3, "robust planar");
            ThrowsStatus(Status.InvalidArgument, () => OrientedBoundingBox.CreateFromPoints(new double[] { 0, 0, double.NaN, 1, 0, 0, 0, 1, 0, 0, 0, 1 }), "NaN");
            Throws<ArgumentException>(() => new OrientedBoundingBox(new double[3], new double[8], new double[3]), "R of 8 values");
        });

        Run("crop by an oriented box", () =>
        {
            // A box along the diagonal x = y (45 degrees about z), 2 long, 0.2 wide and high.
            double c = Math.Sqrt(0.5);
            var box = new OrientedBoundingBox(new double[] { 0, 0, 0 }, new[] { c, -c, 0, c, c, 0, 0, 0, 1 }, new[] { 2, 0.2, 0.2 });
            using (var pc = new PointCloud(new double[] { 0.5, 0.5, 0, -0.5, -0.5, 0, 0.5, -0.5, 0, 0, 0, 0 }))
            {
                Check(box.GetPointIndicesWithinBoundingBox(pc.Points).SequenceEqual(new[] { 0, 1, 3 }), "indices within");
                using (var inside = pc.Crop(box)) Check(SameRows(inside.Points, new double[] { 0.5, 0.5, 0, -0.5, -0.5, 0, 0, 0, 0 }, 0), "inside");
                using (var outside = pc.Crop(box, true)) AllNear(outside.Points, new[] { 0.5, -0.5, 0 }, 0, "outside");
                Throws<ArgumentNullException>(() => pc.Crop((OrientedBoundingBox)null), "null box");
            }
            using (var mesh = TriangleMesh.CreateBox())
            {
                var bottom = OrientedBoundingBox.CreateFromAxisAlignedBoundingBox(new[] { -0.1, -0.1, -0.1 }, new[] { 1.1, 1.1, 0.5 });
                using (var cut = mesh.Crop(bottom))
                {
                    Check(cut.NumVertices == 4 && cut.NumTriangles == 2, "bottom face: " + cut.NumVertices + " vertices, " + cut.NumTriangles + " triangles");
                    foreach (var z in cut.Vertices.Where((x, i) => i % 3 == 2)) Near(z, 0, 0, "bottom z");
                }
            }
        });

        Run("line sets", () =>
        {
            using (var ls = LineSet.CreateFromAxisAlignedBoundingBox(new double[] { 0, 0, 0 }, new double[] { 1, 2, 3 }))
            {
                Check(ls.NumPoints == 8 && ls.NumLines == 12, "8 points, 12 lines");
                var p = ls.Points; var l = ls.Lines;
                var lengths = new int[4];
                for (int i = 0; i < 12; i++)
                {
                    int a = l[2 * i], b = l[2 * i + 1];
                    double d = Math.Sqrt(Math.Pow(p[3 * a] - p[3 * b], 2) + Math.Pow(p[3 * a + 1] - p[3 * b + 1], 2) + Math.Pow(p[3 * a + 2] - p[3 * b + 2], 2));
                    int k = (int)Math.Round(d);
                    Near(d, k, 1e-12, "edge length");
                    Check(k >= 1 && k <= 3, "edge along an axis");
                    lengths[k]++;
                }
                Check(lengths[1] == 4 && lengths[2] == 4 && lengths[3] == 4, "4 edges of each length");
                var obb = OrientedBoundingBox.CreateFromAxisAlignedBoundingBox(new double[] { 0, 0, 0 }, new double[] { 1, 2, 3 });
                using (var lo = LineSet.CreateFromOrientedBoundingBox(obb))
                {
                    AllNear(lo.Points, obb.GetBoxPoints(), 1e-12, "points in box-point order");
                    Check(lo.NumLines == 12, "obb lines");
                }
                ls.PaintUniformColor(new[] { 1, 0.5, 0 });
                Check(ls.Colors.Length == 36 && ls.Colors[1] == 0.5, "colors per line");
                ls.Transform(new double[] { 1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 });
                Near(ls.Points[0], p[0] + 10, 0, "translated");
                long rows; var view = ls.LinesView(out rows);
                Check(rows == 12 && view != IntPtr.Zero, "lines view");
                var copy = new int[24]; Marshal.Copy(view, copy, 0, 24);
                Check(copy.SequenceEqual(ls.Lines), "view == copy");
                using (var c = ls.Clone()) { ls.Lines = new int[0]; Check(c.NumLines == 12 && ls.NumLines == 0, "deep clone"); }
            }
            using (var box = TriangleMesh.CreateBox())
            using (var edges = LineSet.CreateFromTriangleMesh(box))
                Check(edges.NumPoints == 8 && edges.NumLines == 18, "box mesh: 12 edges + 6 diagonals, got " + edges.NumLines);
            using (var a = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0 }))
            using (var b = new PointCloud(new double[] { 0, 1, 0, 1, 1, 0, 2, 1, 0 }))
            {
                using (var corr = LineSet.CreateFromPointCloudCorrespondences(a, b, new[] { 0, 2, 1, 0 }))
                {
                    Check(corr.NumPoints == 5, "points of both clouds");
                    Check(corr.Lines.SequenceEqual(new[] { 0, 4, 1, 2 }), "lines offset into cloud1: " + string.Join(",", corr.Lines));
                }
                ThrowsStatus(Status.InvalidArgument, () => LineSet.CreateFromPointCloudCorrespondences(a, b, new[] { 0, 3 }), "pair out of range");
                Throws<ArgumentException>(() => LineSet.CreateFromPointCloudCorrespondences(a, b, new[] { 0 }), "odd pairs");
            }
            using (var ls = new LineSet(new double[] { 0, 0, 0, 1, 1, 1 }, new[] { 0, 1 }))
            {
                Check(ls.NumPoints == 2 && ls.NumLines == 1 && ls.Lines.SequenceEqual(new[] { 0, 1 }), "constructed");
                Throws<ArgumentException>(() => ls.Lines = new[] { 0, 1, 2 }, "odd line array");
                Throws<ArgumentException>(() => ls.Points = new double[] { 0, 1 }, "points not a multiple of 3");
                ls.Dispose();
                Throws<ObjectDisposedException>(() => { var n = ls.NumLines; }, "after Dispose");
            }
        });

        Run("voxel grids", () =>
        {
            using (var pc = new PointCloud(new double[] { 0, 0, 0, 0.05, 0.05, 0.05, 1, 0, 0, 0, 0, 1 }))
            {
                pc.Colors = new double[] { 1, 0, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1 };
                using (var grid = VoxelGrid.CreateFromPointCloud(pc, 0.5))
                {
                    Near(grid.VoxelSize, 0.5, 0, "voxel size");
                    AllNear(grid.Origin, new[] { -0.25, -0.25, -0.25 }, 1e-15, "origin = min - size / 2");
                    Check(grid.NumVoxels == 3, "3 voxels");
                    var v = grid.GetVoxels();
                    Check(v.Count == 3 && v.GridIndices.SequenceEqual(new[] { 0, 0, 0, 0, 0, 2, 2, 0, 0 }), "sorted grid indices " + string.Join(",", v.GridIndices));
                    AllNear(v.Colors, new double[] { 0.5, 0, 0.5, 1, 1, 1, 0, 1, 0 }, 1e-12, "mean colors");
                    Check(grid.GetVoxel(new double[] { 1, 0, 0 }).SequenceEqual(new[] { 2, 0, 0 }), "get voxel");
                    Check(grid.CheckIfIncluded(new double[] { 1, 0, 0, 0.5, 0.5, 0.5 }).SequenceEqual(new[] { true, false }), "included");
                    Throws<ArgumentException>(() => grid.GetVoxel(new double[] { 1, 0 }), "point of 2 values");
                }
                using (var grid = VoxelGrid.CreateFromPointCloudWithinBounds(pc, 1, new double[] { 0, 0, 0 }, new double[] { 2, 2, 2 }))
                {
                    AllNear(grid.Origin, new double[] { 0, 0, 0 }, 0, "bounded origin");
                    Check(grid.GetVoxels().GridIndices.SequenceEqual(new[] { 0, 0, 0, 0, 0, 1, 1, 0, 0 }), "bounded grid indices");
                }
                ThrowsStatus(Status.InvalidArgument, () => VoxelGrid.CreateFromPointCloud(pc, 0), "voxel size 0");
                ThrowsStatus(Status.InvalidArgument, () => VoxelGrid.CreateFromPointCloud(pc, double.NaN), "voxel size NaN");
            }
            using (var box = TriangleMesh.CreateBox())
            using (var grid = VoxelGrid.CreateFromTriangleMesh(box, 0.5))
            {
                Check(grid.NumVoxels == 26, "surface voxels of a unit box: " + grid.NumVoxels);
                Check(grid.CheckIfIncluded(new[] { 0.5, 0.5, 0.5, 0, 0, 0 }).SequenceEqual(new[] { false, true }), "hollow");
            }
        });

        Run("octree", () =>
        {
            using (var pc = new PointCloud(new double[] { 0, 0, 0, 1, 1, 1, 0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.2, 0.1, 0.1 }))
            using (var tree = new Octree(2))
            {
                pc.Colors = new double[] { 0.3, 0, 0, 1, 1, 1, 0.6, 0, 0, 0, 0, 0, 0, 0.9, 0 };
                tree.ConvertFromPointCloud(pc);
                AllNear(tree.Origin, new double[] { 0, 0, 0 }, 0, "root origin");
                Near(tree.Size, 1.01, 1e-12, "root size (1% expansion)");
                Check(tree.MaxDepth == 2 && tree.NumLeafNodes == 2, "depth 2, 2 leaves: " + tree.NumLeafNodes);
                var leaf = tree.LocateLeafNode(new[] { 0.05, 0.05, 0.05 });
                Check(leaf != null && leaf.Indices.SequenceEqual(new[] { 0, 2, 4 }), "leaf indices");
                AllNear(leaf.Color, new[] { 0.3, 0.3, 0 }, 1e-12, "mean color");
                AllNear(leaf.Info.Origin, new double[] { 0, 0, 0 }, 0, "leaf origin");
                Near(leaf.Info.Size, 0.2525, 1e-12, "leaf size");
                Check(leaf.Info.Depth == 2 && leaf.Info.ChildIndex == 0, "depth / child");
                leaf = tree.LocateLeafNode(new[] { 0.95, 0.95, 0.95 });
                Check(leaf != null && leaf.Indices.SequenceEqual(new[] { 1, 3 }) && leaf.Info.ChildIndex == 7, "far leaf");
                AllNear(leaf.Info.Origin, new[] { 0.7575, 0.7575, 0.7575 }, 1e-12, "far leaf origin");
                Check(tree.LocateLeafNode(new[] { 0.5, 0.5, 0.5 }) == null, "empty cell");
                Check(tree.LocateLeafNode(new double[] { 5, 5, 5 }) == null, "outside the root");
                ThrowsStatus(Status.InvalidArgument, () => tree.LocateLeafNode(new[] { double.NaN, 0, 0 }), "NaN point");
                using (var empty = new PointCloud()) ThrowsStatus(Status.InvalidArgument, () => tree.ConvertFromPointCloud(empty), "empty cloud");
            }
            ThrowsStatus(Status.InvalidArgument, () => new Octree(0), "max depth 0");
        });

        Run("covariances", () =>
        {
            // A planar 10 x 10 patch: every neighbourhood covariance is singular (normal direction z).
            using (var pc = new PointCloud(GridWithOutliers().Take(300).ToArray()))
            {
                Check(!pc.HasCovariances && pc.Covariances.Length == 0, "none yet");
                pc.EstimateCovariances(SearchParam.Knn(10));
                Check(pc.HasCovariances, "estimated");
                var cov = pc.Covariances;
                Check(cov.Length == 900, "9 per point");
                for (int i = 0; i < 100; i++)
                {
                    Near(Det3(cov, 9 * i), 0, 1e-15, "det " + i);
                    Near(cov[9 * i + 8], 0, 0, "zz " + i);
                    Check(cov[9 * i] > 0 && cov[9 * i + 4] > 0, "in-plane variance " + i);
                    Near(cov[9 * i + 1], cov[9 * i + 3], 1e-15, "symmetric " + i);
                }
                long rows; var view = pc.CovariancesView(out rows);
                var copy = new double[900]; Marshal.Copy(view, copy, 0, 900);
                Check(rows == 100 && copy.SequenceEqual(cov), "view == copy");
                using (var some = pc.SelectByIndex(new[] { 5, 7 }))
                    Check(some.Covariances.SequenceEqual(cov.Skip(45).Take(9).Concat(cov.Skip(63).Take(9))), "follow select_by_index");
                // 90 degrees about x: C -> R C R^T moves the zero variance from z to y.
                pc.Rotate(new double[] { 1, 0, 0, 0, 0, -1, 0, 1, 0 });
                var rot = pc.Covariances;
                Near(rot[4], 0, 1e-15, "yy after rotation"); Near(rot[8], cov[4], 1e-15, "zz after rotation");
                pc.Covariances = new double[] { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
                Check(!pc.HasCovariances, "one matrix for 100 points is not has_covariances");
                Throws<ArgumentException>(() => pc.Covariances = new double[10], "not a multiple of 9");
                ThrowsStatus(Status.InvalidArgument, () => pc.EstimateCovariances(SearchParam.Knn(0)), "knn 0");
            }
        });
    }

    static double[] ApplyTransformIdentity() { return new double[] { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 }; }
}
